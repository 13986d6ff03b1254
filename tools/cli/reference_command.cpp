// `mvpl reference`: the CPU path tracer, the ground truth for every error report.
#include <tbb/global_control.h>

#include <cstdio>
#include <memory>

#include "engine/core/error.h"
#include "engine/core/image.h"
#include "engine/core/timer.h"
#include "engine/light/light_sampler.h"
#include "engine/reference/path_tracer.h"
#include "engine/scene/scene_loader.h"
#include "engine/trace/accel.h"
#include "tools/cli/arg_parser.h"
#include "tools/cli/commands.h"
#include "tools/cli/output_check.h"

namespace mvpl::cli {

int run_reference(const Args& args) {
    std::string scene_path;
    reference::PathTracerOptions options;
    std::vector<std::string> outputs;
    float exposure = 0.0f;
    int threads = 0;
    ArgParser parser(
        "reference",
        "Renders SCENE with the CPU reference path tracer (next-event estimation, MIS,\n"
        "Russian roulette). Writes EXR (linear float) or PNG (sRGB) by the extension of -o.");
    parser.add_positional("SCENE", &scene_path, "glTF 2.0 scene (.gltf or .glb)");
    parser.add_int("--spp", &options.spp, "samples per pixel");
    parser.add_int("--max-depth", &options.max_depth,
                   "path segments from the camera to the light (Mitsuba's max_depth; 1 = emitters, "
                   "2 = direct light, -1 = unlimited)");
    parser.add_resolution("--res", &options.width, &options.height, "image size WxH");
    parser.add_uint64("--seed", &options.seed, "random seed; the image is a function of it");
    parser.add_strings("-o", &outputs, "output image, .exr or .png");
    parser.add_float("--exposure", &exposure, "PNG exposure in stops");
    parser.add_int("--threads", &threads, "worker threads (0 = all cores)");
    parser.add_flag("--quiet", &options.quiet, "no progress bar and no summary line");
    if (!parser.parse(args)) return 0;
    if (options.spp < 1) throw UsageError("reference: --spp must be at least 1");
    if (threads < 0) throw UsageError("reference: --threads must not be negative");
    if (outputs.empty()) outputs.push_back("reference.exr");
    check_output_extensions(outputs);
    std::unique_ptr<tbb::global_control> limit;
    if (threads > 0) {
        limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                      threads);
    }

    Timer setup;
    const scene::Scene scene = scene::load_scene(scene_path);
    const trace::Accel accel(scene);
    const light::LightSampler lights(scene);
    const double setup_seconds = setup.seconds();
    if (lights.empty() && !options.quiet) {
        std::fprintf(stderr, "mvpl: warning: %s: the scene has no light; the image is black\n",
                     scene_path.c_str());
    }

    reference::RenderStats stats;
    const reference::PathTracer tracer(scene, accel, lights);
    const Image image = tracer.render(options, &stats);
    for (const std::string& out : outputs)
        write_image(image, out, exposure);

    if (stats.nonfinite_samples > 0) {
        std::fprintf(stderr, "mvpl: warning: %llu non-finite path samples were discarded\n",
                     static_cast<unsigned long long>(stats.nonfinite_samples));
    }
    if (!options.quiet) {
        std::printf(
            "reference: %dx%d, %d spp, max depth %d, %zu triangles: setup %.2f s, render %.2f s, "
            "%.2f Mrays/s, %.2f Mpaths/s\n",
            options.width, options.height, options.spp, options.max_depth, scene.triangle_count(),
            setup_seconds, stats.seconds, double(stats.rays) / stats.seconds * 1e-6,
            double(stats.paths) / stats.seconds * 1e-6);
    }
    return 0;
}

}  // namespace mvpl::cli
