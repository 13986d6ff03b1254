// `mvpl reference`: the CPU path tracer, the ground truth for every error report.
#include <tbb/global_control.h>

#include <cstdio>
#include <memory>
#include <optional>

#include "engine/aov/aov_images.h"
#include "engine/core/error.h"
#include "engine/core/host_memory.h"
#include "engine/core/image.h"
#include "engine/core/timer.h"
#include "engine/reference/path_tracer.h"
#include "tools/cli/arg_parser.h"
#include "tools/cli/commands.h"
#include "tools/cli/exr_outputs.h"
#include "tools/cli/option_groups.h"
#include "tools/cli/output_check.h"
#include "tools/session/scene_session.h"

namespace mvpl::cli {

int run_reference(const Args& args) {
    std::string scene_path;
    reference::PathTracerOptions options;
    std::vector<std::string> outputs;
    std::string aov_list;
    float exposure = 0.0f;
    int threads = 0;
    ArgParser parser(
        "reference",
        "Renders SCENE with the CPU reference path tracer (next-event estimation, MIS,\n"
        "Russian roulette). Writes EXR (linear float) or PNG (sRGB) by the extension of -o.");
    parser.add_positional("SCENE", &scene_path, "scene (.gltf, .glb, .xml, .ply, .obj)");
    parser.add_int("--spp", &options.spp, "samples per pixel");
    parser.add_resolution("--res", &options.width, &options.height, "image size");
    parser.add_strings("-o", &outputs, "output image, .exr or .png", "FILE");
    parser.add_float("--exposure", &exposure, "PNG exposure in stops");
    add_aov_option(parser, &aov_list, &outputs);
    parser.add_int("--threads", &threads, "worker threads (0 = all cores)");
    parser.add_flag("--quiet", &options.quiet, "no progress bar and no summary line");
    add_max_depth_option(parser, options.max_depth);
    add_seed_option(parser, options.seed);
    CameraArgs camera;
    add_camera_options(parser, camera);
    EnvironmentArgs environment;
    add_environment_options(parser, environment);
    SceneFileArgs scene_file;
    add_scene_file_options(parser, scene_file);
    if (!parser.parse(args)) return 0;
    Timer wall;
    if (options.spp < 1) throw UsageError("reference: --spp must be at least 1");
    if (threads < 0) throw UsageError("reference: --threads must not be negative");
    bool defaulted = false;
    outputs = outputs_or(outputs, "reference.exr", defaulted);
    check_outputs(outputs);
    std::unique_ptr<tbb::global_control> limit;
    if (threads > 0) {
        limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                      threads);
    }

    const session::SceneSession session(scene_path, camera.choice, environment.choice,
                                        scene_file.options);
    apply_scene_defaults(parser, session.scene(), &options.max_depth, &options.width,
                         &options.height);
    session.warn_if_no_light("the image is black");
    const std::string shortfall = host_memory_shortfall(
        "a " + std::to_string(options.width) + "x" + std::to_string(options.height) + " image",
        reference::PathTracer::host_bytes(options), host_memory_bytes());
    if (!shortfall.empty()) throw UsageError("reference: " + shortfall);

    reference::RenderStats stats;
    const reference::PathTracer tracer(session.scene(), session.accel(), session.lights());
    const std::vector<aov::AovRequest> aovs =
        aov_requests(parser, aov_list, session.scene(), outputs);
    std::optional<aov::ReferenceAovs> aov_film;
    if (!aovs.empty()) aov_film.emplace(session.scene(), session.accel(), options, aovs);
    const Image image =
        tracer.render(options, &stats, aov_film ? aov_film->hook() : reference::CameraSampleHook{});
    session.warn_if_black(image);
    ExrExtras extras;
    if (aov_film) extras.layers = aov_film->images();
    extras.attributes = run_attributes(
        {"reference", &args, options.seed, std::nullopt, options.spp, wall.seconds()});
    write_images(image, outputs, exposure, extras);
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
