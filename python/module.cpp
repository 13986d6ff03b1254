// The Python module `mvpl` (issue 34): load a scene, render it with VPLs or the reference path
// tracer into numpy arrays, compare images. Keywords are the command line's options (underscores
// for dashes), parsed by its option tables (keyword_args.h), so that names, defaults and checks
// are the command line's:
//     import mvpl
//     img = mvpl.render(mvpl.load_file("scene.gltf"), vpls=4096)
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "engine/core/image_metrics.h"
#include "python/errors.h"
#include "python/image_array.h"
#include "python/keyword_args.h"
#include "python/path_trace.h"
#include "python/scene_handle.h"
#include "python/vpl_render.h"
#include "tools/cli/error_json.h"

namespace py = pybind11;
using namespace mvpl::python;

namespace {

// -a PATH for each of `assets` (a path or a list of them), -D NAME=VALUE for each define.
std::vector<std::string> load_tokens(const py::object& assets, const py::kwargs& defines) {
    std::vector<std::string> tokens;
    if (py::isinstance<py::str>(assets)) {
        tokens = {"-a", assets.cast<std::string>()};
    } else if (!assets.is_none()) {
        for (const py::handle path : assets)
            tokens.insert(tokens.end(), {"-a", py::str(path).cast<std::string>()});
    }
    for (const auto& [name, value] : defines) {
        // Mitsuba spells booleans in lower case.
        const std::string text = py::isinstance<py::bool_>(value)
                                     ? (value.cast<bool>() ? "true" : "false")
                                     : py::str(value).cast<std::string>();
        tokens.insert(tokens.end(), {"-D", name.cast<std::string>() + "=" + text});
    }
    return tokens;
}

// The keywords as command-line tokens, with aovs (names ("albedo", …) or one comma-separated
// string) as `--aov`.
std::vector<std::string> render_tokens(const py::object& aovs, const py::kwargs& options) {
    std::vector<std::string> tokens = keyword_tokens(options);
    if (!aovs.is_none()) {
        std::string list = py::isinstance<py::str>(aovs) ? aovs.cast<std::string>() : "";
        if (!py::isinstance<py::str>(aovs)) {
            for (const py::handle name : aovs)
                list += (list.empty() ? "" : ",") + py::str(name).cast<std::string>();
        }
        tokens.insert(tokens.end(), {"--aov", list});
    }
    return tokens;
}

// Between chunks, with the GIL: Ctrl-C (Python's SIGINT handler only sets a flag) raises
// KeyboardInterrupt, then the progress callback, if any, gets the share done.
ChunkHook between_chunks(const py::object& progress) {
    return [&progress](double done) {
        if (PyErr_CheckSignals() != 0) throw py::error_already_set();
        if (!progress.is_none()) progress(done);
    };
}

// The image, or with aovs the image and a dict of the AOV arrays.
py::object arrays(const RenderResult& result, const py::object& aovs) {
    if (aovs.is_none()) return to_array(result.image);
    py::dict layers;
    for (const mvpl::ChannelImage& layer : result.aovs)
        layers[py::str(layer.name)] = to_array(layer);
    return py::make_tuple(to_array(result.image), layers);
}

py::object render(const SceneHandle& scene, const py::object& progress, const py::object& aovs,
                  const py::kwargs& options) {
    return arrays(render_vpls(scene, render_tokens(aovs, options), between_chunks(progress)), aovs);
}

py::object reference(const SceneHandle& scene, const py::object& progress, const py::object& aovs,
                     const py::kwargs& options) {
    return arrays(path_trace(scene, render_tokens(aovs, options), between_chunks(progress)), aovs);
}

py::dict compare(const py::object& image, const py::object& reference) {
    const mvpl::ImageError e =
        mvpl::compare_images(to_image(image, "image"), to_image(reference, "reference"));
    return py::module_::import("json").attr("loads")(mvpl::cli::error_json(e, std::nullopt).dump());
}

}  // namespace

PYBIND11_MODULE(mvpl, m) {
    m.doc() =
        "mvpl: Metropolis virtual-point-light renderer. Keywords are the command line's "
        "options (`mvpl render --help`), with underscores for dashes.";
    register_error_translation();
    py::class_<SceneHandle>(m, "Scene", "A scene file loaded by load_file.")
        .def_property_readonly("path", &SceneHandle::path)
        .def("__repr__", [](const SceneHandle& s) { return "mvpl.Scene('" + s.path() + "')"; });
    m.def(
        "load_file",
        [](const std::string& path, const py::object& assets, const py::kwargs& defines) {
            std::vector<std::string> tokens = load_tokens(assets, defines);
            const py::gil_scoped_release unlocked;
            return SceneHandle(path, std::move(tokens));
        },
        py::arg("path"), py::kw_only(), py::arg("assets") = py::none(),
        "Loads a scene: glTF (.gltf, .glb), Mitsuba XML (.xml), PLY or OBJ. `assets`: folders "
        "where a Mitsuba scene's relative file names are searched (-a); other keywords are its "
        "parameters (-D NAME=VALUE). Bad input raises ValueError with mvpl's one-line message.");
    m.def("render", &render, py::arg("scene"), py::kw_only(), py::arg("progress") = py::none(),
          py::arg("aovs") = py::none(),
          "Renders with virtual point lights on the GPU: a float32 array height x width x 3, "
          "the image `mvpl render` writes for the same options; with aovs=('albedo', 'normal', "
          "'depth', 'position') (any of them), the image and a dict of height x width x C "
          "arrays. Keywords are its options, e.g. "
          "vpls=4096, time_budget=10, sampler='metropolis', res=(640, 480), seed=1, "
          "no_caustics=True. progress: called between chunks with the share done (0..1). "
          "Ctrl-C interrupts between chunks.");
    m.def("reference", &reference, py::arg("scene"), py::kw_only(),
          py::arg("progress") = py::none(), py::arg("aovs") = py::none(),
          "Renders with the CPU reference path tracer: a float32 array height x width x 3, as "
          "`mvpl reference` writes it (with aovs, the image and a dict of AOV arrays, as "
          "render). Keywords are its options, e.g. spp=256, max_depth=6. progress: called "
          "between chunks of samples per pixel with the share done (0..1). Ctrl-C interrupts "
          "between chunks (about half a second each).");
    m.def("compare", &compare, py::arg("image"), py::arg("reference"),
          "The error of `image` against `reference` (arrays height x width x 3 or EXR paths): the "
          "dict of `mvpl compare --json` (relMSE, RMSE, mean_abs, mean_ratio, rel_err_p999, "
          "max_ratio).");
}
