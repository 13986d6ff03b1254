#include "tools/cli/reference_args.h"
#include "tools/cli/exr_outputs.h"

#include "engine/core/error.h"
#include "engine/core/host_memory.h"

namespace mvpl::cli {

void add_reference_options(ArgParser& parser, ReferenceArgs& a) {
    parser.add_positional("SCENE", &a.scene_path, "scene (.gltf, .glb, .xml, .ply, .obj)");
    parser.add_int("--spp", &a.options.spp, "samples per pixel");
    parser.add_resolution("--res", &a.options.width, &a.options.height, "image size");
    parser.add_strings("-o", &a.outputs, "output image, .exr or .png", "FILE");
    add_write_every_option(parser, a.write_every, "reference");
    parser.add_float("--exposure", &a.exposure, "PNG exposure in stops");
    add_aov_option(parser, &a.aov_list, &a.outputs);
    parser.add_int("--threads", &a.threads, "worker threads (0 = all cores)");
    parser.add_flag("--quiet", &a.options.quiet, "no progress bar and no summary line");
    add_max_depth_option(parser, a.options.max_depth);
    add_seed_option(parser, a.options.seed);
    add_camera_options(parser, a.camera);
    add_environment_options(parser, a.environment);
    add_scene_file_options(parser, a.scene_file);
    parser.add_check([&a] {
        if (a.options.spp < 1) throw UsageError("reference: --spp must be at least 1");
        if (a.threads < 0) throw UsageError("reference: --threads must not be negative");
    });
}

void check_host_memory(const reference::PathTracerOptions& options) {
    const std::string shortfall = host_memory_shortfall(
        "a " + std::to_string(options.width) + "x" + std::to_string(options.height) + " image",
        reference::PathTracer::host_bytes(options), host_memory_bytes());
    if (!shortfall.empty()) throw UsageError("reference: " + shortfall);
}

}  // namespace mvpl::cli
