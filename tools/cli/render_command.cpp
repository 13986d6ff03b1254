// `mvpl render`: VPLs from a sampler, shaded on the GPU (or by the CPU oracle with --oracle).
#include <cstdio>
#include <memory>

#include "engine/core/error.h"
#include "engine/core/image.h"
#include "engine/core/progress.h"
#include "engine/core/timer.h"
#include "engine/gpu/context.h"
#include "engine/gpu/device_info.h"
#include "engine/light/light_sampler.h"
#include "engine/reference/vpl_gather.h"
#include "engine/render/vpl_renderer.h"
#include "engine/scene/scene_loader.h"
#include "engine/trace/accel.h"
#include "sampler/monte_carlo_sampler.h"
#include "tools/cli/arg_parser.h"
#include "tools/cli/commands.h"
#include "tools/cli/output_check.h"

namespace mvpl::cli {

namespace {

// Default clamping distance, as a fraction of the scene's bounding-box diagonal. Measured on the
// Cornell box (256 paths, 256², against Mitsuba): relMSE 0.039 unclamped, 0.015 at 0.01, 0.0073 at
// 0.02, 0.0034 at 0.05, 0.0032 at 0.1, while the mean darkens by 0.5–1% at 0.05 and 1.5–2% at
// 0.1 — 0.05 removes nearly all of the singularity's noise for half the bias of 0.1.
constexpr float kDefaultClamp = 0.05f;

}  // namespace

int run_render(const Args& args) {
    std::string scene_path;
    std::string sampler_name = "mc";
    std::string per_path = "all";
    uint64_t paths = 1024;
    int width = 256, height = 256;
    int shadow_res = 256;
    int batch = 32;
    float clamp = kDefaultClamp;
    int max_depth = 6;
    uint64_t seed = 0;
    std::vector<std::string> outputs;
    float exposure = 0.0f;
    int device = -1;
    bool qmc = false, oracle = false, quiet = false;
    ArgParser parser(
        "render",
        "Renders SCENE with virtual point lights: a sampler traces light paths on the CPU\n"
        "and leaves VPLs; the GPU shades them in batches with cube-map shadows.");
    parser.add_positional("SCENE", &scene_path, "glTF 2.0 scene (.gltf or .glb)");
    parser.add_uint64(
        "--vpls", &paths,
        "light paths to trace; each leaves one VPL per bounce (--vpl-per-path all) or one");
    parser.add_string("--sampler", &sampler_name, "VPL sampler: mc (default)");
    parser.add_flag("--qmc", &qmc, "Halton primary samples instead of random ones (mc)");
    parser.add_string("--vpl-per-path", &per_path,
                      "all (default) or one (the seed paper's choice)");
    parser.add_resolution("--res", &width, &height, "image size WxH");
    parser.add_int("--shadow-res", &shadow_res, "side of a shadow cube face in texels");
    parser.add_int("--batch", &batch, "VPLs per shadow/shading batch");
    parser.add_float("--clamp", &clamp,
                     "clamping distance as a fraction of the scene diagonal (0 = off)");
    parser.add_int(
        "--max-depth", &max_depth,
        "path segments from the camera to the light (Mitsuba's max_depth; -1 = unlimited)");
    parser.add_uint64("--seed", &seed, "random seed");
    parser.add_strings("-o", &outputs, "output image, .exr or .png");
    parser.add_float("--exposure", &exposure, "PNG exposure in stops");
    parser.add_int("--device", &device, "Vulkan device index (see mvpl info); -1 = default");
    parser.add_flag("--oracle", &oracle,
                    "shade on the CPU with exact visibility instead of the GPU");
    parser.add_flag("--quiet", &quiet, "no progress bar and no summary line");
    if (!parser.parse(args)) return 0;
    if (sampler_name != "mc")
        throw UsageError("render: unknown --sampler '" + sampler_name + "' (available: mc)");
    if (per_path != "all" && per_path != "one")
        throw UsageError("render: --vpl-per-path must be all or one");
    if (paths < 1 || paths > (uint64_t(1) << 32))
        throw UsageError("render: --vpls must be in 1..2^32");
    if (shadow_res < 4 || shadow_res > 4096)
        throw UsageError("render: --shadow-res must be in 4..4096");
    if (batch < 1 || batch > 256) throw UsageError("render: --batch must be in 1..256");
    if (!(clamp >= 0.0f && clamp <= 1.0f)) throw UsageError("render: --clamp must be in [0, 1]");
    if (!oracle && device >= 0) {
        const size_t count = gpu::enumerate_devices().size();
        if (size_t(device) >= count) {
            throw UsageError("render: --device " + std::to_string(device) +
                             ": no such Vulkan device (there are " + std::to_string(count) +
                             "; see mvpl info)");
        }
    }
    if (outputs.empty()) outputs.push_back("render.exr");
    check_output_extensions(outputs);

    Timer total;
    const scene::Scene scene = scene::load_scene(scene_path);
    const trace::Accel accel(scene);
    const light::LightSampler lights(scene);
    if (lights.empty() && !quiet) {
        std::fprintf(stderr,
                     "mvpl: warning: %s: the scene has no light; the image shows emitters only\n",
                     scene_path.c_str());
    }

    sampler::MonteCarloOptions mc;
    mc.paths = paths;
    mc.seed = seed;
    mc.qmc = qmc;
    mc.per_path = per_path == "one" ? sampler::VplsPerPath::One : sampler::VplsPerPath::All;
    mc.tracer.max_depth = max_depth;
    mc.quiet = quiet;
    sampler::SamplerStats sampling;
    const std::vector<light::Vpl> vpls =
        sampler::MonteCarloSampler(scene, accel, lights).generate(mc, &sampling);

    Timer shading;
    Image image;
    std::string pass_times;
    if (oracle) {
        reference::GatherOptions g;
        g.width = width;
        g.height = height;
        g.clamp = clamp;
        g.max_depth = max_depth;
        g.quiet = quiet;
        image = reference::gather_vpls(scene, accel, vpls, g);
        pass_times = "CPU oracle";
    } else {
        gpu::ContextOptions co;
        co.device_index = device;
        gpu::Context context(co);
        render::VplRenderer renderer(context, scene);
        render::RenderOptions ro;
        ro.width = uint32_t(width);
        ro.height = uint32_t(height);
        ro.shadow_resolution = uint32_t(shadow_res);
        ro.batch = uint32_t(batch);
        ro.clamp = clamp;
        Progress progress("render", int64_t(vpls.size()), quiet);
        ro.on_batch = [&progress](size_t count) { progress.advance(int64_t(count)); };
        render::RenderTimings t;
        image = renderer.render(vpls, ro, &t);
        progress.finish();
        // MVPL_VALIDATION=1: whatever the layer reported is shown, one line a message.
        for (const std::string& message : context.validation_messages()) {
            std::fprintf(stderr, "mvpl: validation: %s\n", message.c_str());
        }
        char buf[160];
        std::snprintf(buf, sizeof buf,
                      "G-buffer %.1f ms, shadow %.1f ms, shading %.1f ms, %u batches",
                      t.g_buffer_ms, t.shadow_ms, t.shading_ms, t.batches);
        pass_times = buf;
    }
    const double shading_seconds = shading.seconds();
    for (const std::string& out : outputs)
        write_image(image, out, exposure);

    if (!quiet) {
        std::printf(
            "render: %zu VPLs from %llu paths, %dx%d: sampling %.2f s, shading %.2f s (%s), "
            "total %.2f s, %.1f VPL/s\n",
            vpls.size(), static_cast<unsigned long long>(sampling.paths), width, height,
            sampling.seconds, shading_seconds, pass_times.c_str(), total.seconds(),
            double(vpls.size()) / std::max(shading_seconds + sampling.seconds, 1e-9));
    }
    return 0;
}

}  // namespace mvpl::cli
