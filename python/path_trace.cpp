#include "python/path_trace.h"

#include <pybind11/pybind11.h>
#include <tbb/global_control.h>

#include <memory>
#include <optional>

#include "engine/aov/aov_images.h"
#include "engine/aov/aov_kind.h"
#include "engine/core/error.h"
#include "engine/reference/path_film.h"
#include "engine/reference/path_tracer.h"
#include "engine/reference/progressive_trace.h"
#include "tools/cli/reference_args.h"

namespace py = pybind11;

namespace mvpl::python {

RenderResult path_trace(const SceneHandle& scene, const std::vector<std::string>& tokens,
                        const ChunkHook& between_chunks) {
    cli::ReferenceArgs a;
    cli::ArgParser parser("reference", "");
    cli::add_reference_options(parser, a);
    std::vector<std::string> line = scene.command_line();
    line.insert(line.end(), tokens.begin(), tokens.end());
    if (!parser.parse(line))
        throw UsageError("reference: the options are `mvpl reference --help`'s");
    if (parser.given("--write-every") || parser.given("-o"))
        throw UsageError(
            "reference: mvpl.reference returns arrays and writes no file (no -o, no "
            "--write-every)");
    reference::PathTracerOptions& options = a.options;
    options.quiet = true;  // no progress bar on the caller's terminal
    std::unique_ptr<tbb::global_control> limit;
    if (a.threads > 0) {
        limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                      a.threads);
    }
    const py::gil_scoped_release unlocked;
    const std::shared_ptr<const session::SceneSession> session =
        scene.session_for(parser, a.camera.choice, a.environment.choice);
    cli::apply_scene_defaults(parser, session->scene(), &options.max_depth, &options.width,
                              &options.height);
    session->warn_if_no_light("the image is black");
    cli::check_host_memory(options);
    const reference::PathTracer tracer(session->scene(), session->accel(), session->lights());
    // As `mvpl reference` writes them (no EXR to name: --aov alone asks for them here).
    std::optional<aov::ReferenceAovs> aovs;
    if (parser.given("--aov")) {
        aovs.emplace(session->scene(), session->accel(), options,
                     aov::parse_aov_list(a.aov_list, "reference: --aov"));
    }
    reference::PathFilm film(options.width, options.height, options.seed);
    reference::RenderStats stats;
    reference::trace_progressively(tracer, film, options, &stats,
                                   aovs ? aovs->hook() : reference::CameraSampleHook{},
                                   [&](const reference::PathFilm& so_far) {
                                       const py::gil_scoped_acquire locked;
                                       between_chunks(double(so_far.spp()) / double(options.spp));
                                       return true;
                                   });
    {
        const py::gil_scoped_acquire locked;
        between_chunks(1.0);
    }
    RenderResult result{film.image(), {}};
    if (aovs) result.aovs = aovs->images(film.spp());
    session->warn_if_black(result.image);
    return result;
}

}  // namespace mvpl::python
