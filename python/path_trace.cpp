#include "python/path_trace.h"

#include <pybind11/pybind11.h>
#include <tbb/global_control.h>

#include <memory>

#include "engine/core/error.h"
#include "engine/reference/path_tracer.h"
#include "tools/cli/reference_args.h"

namespace py = pybind11;

namespace mvpl::python {

Image path_trace(const SceneHandle& scene, const std::vector<std::string>& tokens) {
    cli::ReferenceArgs a;
    cli::ArgParser parser("reference", "");
    cli::add_reference_options(parser, a);
    std::vector<std::string> line = scene.command_line();
    line.insert(line.end(), tokens.begin(), tokens.end());
    if (!parser.parse(line))
        throw UsageError("reference: the options are `mvpl reference --help`'s");
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
    Image image = tracer.render(options);
    session->warn_if_black(image);
    return image;
}

}  // namespace mvpl::python
