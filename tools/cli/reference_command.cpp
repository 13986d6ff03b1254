// `mvpl reference`: the CPU path tracer, the ground truth for every error report.
#include <tbb/global_control.h>

#include <cstdio>
#include <memory>
#include <optional>

#include "engine/aov/aov_images.h"
#include "engine/core/error.h"
#include "engine/core/image.h"
#include "engine/core/timer.h"
#include "engine/reference/path_tracer.h"
#include "tools/cli/arg_parser.h"
#include "tools/cli/commands.h"
#include "tools/cli/exr_outputs.h"
#include "tools/cli/option_groups.h"
#include "tools/cli/output_check.h"
#include "tools/cli/reference_args.h"
#include "tools/session/scene_session.h"

namespace mvpl::cli {

int run_reference(const Args& args) {
    ReferenceArgs a;
    ArgParser parser(
        "reference",
        "Renders SCENE with the CPU reference path tracer (next-event estimation, MIS,\n"
        "Russian roulette). Writes EXR (linear float) or PNG (sRGB) by the extension of -o.");
    add_reference_options(parser, a);
    if (!parser.parse(args)) return 0;
    reference::PathTracerOptions& options = a.options;
    std::vector<std::string>& outputs = a.outputs;
    const int threads = a.threads;
    Timer wall;
    bool defaulted = false;
    outputs = outputs_or(outputs, "reference.exr", defaulted);
    check_outputs(outputs);
    std::unique_ptr<tbb::global_control> limit;
    if (threads > 0) {
        limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                      threads);
    }

    const session::SceneSession session(a.scene_path, a.camera.choice, a.environment.choice,
                                        a.scene_file.options);
    apply_scene_defaults(parser, session.scene(), &options.max_depth, &options.width,
                         &options.height);
    session.warn_if_no_light("the image is black");
    check_host_memory(options);

    reference::RenderStats stats;
    const reference::PathTracer tracer(session.scene(), session.accel(), session.lights());
    const std::vector<aov::AovRequest> aovs =
        aov_requests(parser, a.aov_list, session.scene(), outputs);
    std::optional<aov::ReferenceAovs> aov_film;
    if (!aovs.empty()) aov_film.emplace(session.scene(), session.accel(), options, aovs);
    const Image image =
        tracer.render(options, &stats, aov_film ? aov_film->hook() : reference::CameraSampleHook{});
    session.warn_if_black(image);
    ExrExtras extras;
    if (aov_film) extras.layers = aov_film->images();
    extras.attributes = run_attributes(
        {"reference", &args, options.seed, std::nullopt, options.spp, wall.seconds()});
    write_images(image, outputs, a.exposure, extras);
    say_written("reference", outputs, defaulted, options.quiet);

    if (stats.nonfinite_samples > 0) {
        std::fprintf(stderr, "mvpl: warning: %llu non-finite path samples were discarded\n",
                     static_cast<unsigned long long>(stats.nonfinite_samples));
    }
    if (!options.quiet) {
        std::printf(
            "reference: %dx%d, %d spp, max depth %d, %zu triangles: setup %.2f s, render %.2f s, "
            "%.2f Mrays/s, %.2f Mpaths/s\n",
            options.width, options.height, options.spp, options.max_depth,
            session.scene().triangle_count(), session.setup_seconds(), stats.seconds,
            double(stats.rays) / stats.seconds * 1e-6, double(stats.paths) / stats.seconds * 1e-6);
    }
    return 0;
}

}  // namespace mvpl::cli
