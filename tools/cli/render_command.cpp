// `mvpl render`: VPLs from a sampler, shaded on the GPU (or by the CPU oracle with --oracle).
#include <algorithm>
#include <cmath>
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
#include "sampler/metropolis_stream.h"
#include "sampler/monte_carlo_sampler.h"
#include "sampler/sampler_factory.h"
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

// Seconds of sampling + shading aimed at per progressive chunk under --time-budget: long enough
// that a Metropolis chain merges its repeats over several steps, short enough that the last
// chunk overshoots the budget by little.
constexpr double kChunkSeconds = 0.5;

// Warns when the Metropolis bootstrap found no light on anything the camera sees; returns
// whether it did not (then sampling longer cannot change the black image).
bool warn_if_unlit(const sampler::VplStream& stream, const std::string& scene_path) {
    const auto* metropolis = dynamic_cast<const sampler::MetropolisStream*>(&stream);
    if (metropolis && metropolis->no_visible_light()) {
        std::fprintf(stderr,
                     "mvpl: warning: %s: no light reaches anything the camera sees; the image "
                     "is black\n",
                     scene_path.c_str());
        return true;
    }
    return false;
}

// The next chunk of work units: about kChunkSeconds at the rate measured so far, never past the
// remaining budget's worth, at least one unit.
uint64_t next_chunk(uint64_t done, double elapsed, double remaining, uint64_t first) {
    if (done == 0 || !(elapsed > 0.0)) return first;
    const double per_unit = elapsed / double(done);
    const double seconds = std::min(kChunkSeconds, remaining);
    // At most 2^20 units a chunk, however cheap they were so far.
    return std::clamp<uint64_t>(uint64_t(std::min(seconds / per_unit, 1e9)), 1, uint64_t(1) << 20);
}

}  // namespace

int run_render(const Args& args) {
    std::string scene_path;
    std::string sampler_name = "mc";
    std::string per_path;  // empty: each sampler's default
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
    std::string dump_shaders;
    bool no_shader_cache = false;
    float time_budget = 0.0f;
    sampler::SamplerSettings settings;
    ArgParser parser(
        "render",
        "Renders SCENE with virtual point lights: a sampler traces light paths on the CPU\n"
        "and leaves VPLs; the GPU shades them in batches with cube-map shadows.");
    parser.add_positional("SCENE", &scene_path, "glTF 2.0 scene (.gltf or .glb)");
    parser.add_uint64("--vpls", &paths,
                      "mc: light paths to trace, each leaves one VPL per bounce (--vpl-per-path "
                      "all) or one; metropolis: chain steps");
    parser.add_string("--sampler", &sampler_name, "VPL sampler: mc (default) or metropolis");
    parser.add_float(
        "--time-budget", &time_budget,
        "seconds of sampling + shading: render as many VPLs as fit (overrides --vpls)");
    parser.add_flag("--qmc", &qmc, "Halton primary samples instead of random ones (mc)");
    parser.add_string("--vpl-per-path", &per_path,
                      "all or one (the seed paper's choice); default all for mc, one for "
                      "metropolis");
    parser.add_float("--beta", &settings.large_step, "metropolis: large-step probability");
    parser.add_float("--sigma", &settings.sigma,
                     "metropolis: small-step width in primary sample space");
    parser.add_int("--chains", &settings.chains, "metropolis: independent chains");
    parser.add_int("--importance-points", &settings.importance_points,
                   "metropolis: camera-visible points of the target");
    parser.add_uint64("--bootstrap", &settings.bootstrap,
                      "metropolis: independent paths for the normalisation");
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
    parser.add_string("--dump-shaders", &dump_shaders,
                      "write the GLSL generated for this scene, every stage, into DIR");
    parser.add_flag("--no-shader-cache", &no_shader_cache,
                    "compile every shader; neither read nor write the SPIR-V cache");
    if (!parser.parse(args)) return 0;
    const std::vector<std::string>& names = sampler::sampler_names();
    if (std::find(names.begin(), names.end(), sampler_name) == names.end())
        throw UsageError("render: unknown --sampler '" + sampler_name +
                         "' (available: mc, metropolis)");
    if (!per_path.empty() && per_path != "all" && per_path != "one")
        throw UsageError("render: --vpl-per-path must be all or one");
    if (paths < 1 || paths > (uint64_t(1) << 32))
        throw UsageError("render: --vpls must be in 1..2^32");
    if (shadow_res < 4 || shadow_res > 4096)
        throw UsageError("render: --shadow-res must be in 4..4096");
    if (batch < 1 || batch > 256) throw UsageError("render: --batch must be in 1..256");
    if (!(clamp >= 0.0f && clamp <= 1.0f)) throw UsageError("render: --clamp must be in [0, 1]");
    if (!(time_budget >= 0.0f && time_budget <= 1e6f))
        throw UsageError("render: --time-budget must be in [0, 1e6] seconds");
    if (!(settings.large_step >= 0.0f && settings.large_step <= 1.0f))
        throw UsageError("render: --beta must be in [0, 1]");
    if (!(settings.sigma > 0.0f && settings.sigma <= 1.0f))
        throw UsageError("render: --sigma must be in (0, 1]");
    if (settings.chains < 1 || settings.chains > 4096)
        throw UsageError("render: --chains must be in 1..4096");
    if (settings.importance_points < 1 || settings.importance_points > (1 << 20))
        throw UsageError("render: --importance-points must be in 1..2^20");
    if (settings.bootstrap < 1 || settings.bootstrap > (uint64_t(1) << 26))
        throw UsageError("render: --bootstrap must be in 1..2^26");
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

    settings.seed = seed;
    settings.tracer.max_depth = max_depth;
    settings.qmc = qmc;
    settings.per_path = per_path == "one" ? sampler::VplsPerPath::One : sampler::VplsPerPath::All;
    settings.metropolis_per_path =
        per_path == "all" ? sampler::VplsPerPath::All : sampler::VplsPerPath::One;
    settings.width = width;
    settings.height = height;
    settings.clamp = clamp;

    render::RenderOptions ro;
    ro.width = uint32_t(width);
    ro.height = uint32_t(height);
    ro.shadow_resolution = uint32_t(shadow_res);
    ro.batch = uint32_t(batch);
    ro.clamp = clamp;
    ro.dump_shaders = dump_shaders;
    ro.shader_cache = !no_shader_cache;
    ro.surface_vpls = max_depth < 0 || max_depth >= 3;  // surface VPLs light depth ≥ 3
    reference::GatherOptions g;
    g.width = width;
    g.height = height;
    g.clamp = clamp;
    g.max_depth = max_depth;
    g.quiet = quiet;

    std::unique_ptr<gpu::Context> context;
    std::unique_ptr<render::VplRenderer> renderer;
    if (!oracle) {
        gpu::ContextOptions co;
        co.device_index = device;
        context = std::make_unique<gpu::Context>(co);
        renderer = std::make_unique<render::VplRenderer>(*context, scene);
    }

    Image image;
    std::string pass_times = oracle ? "CPU oracle" : "";
    std::string statistics;
    uint64_t units = 0;
    size_t vpl_count = 0;
    double sampling_seconds = 0.0, shading_seconds = 0.0;
    render::RenderTimings t;
    if (time_budget > 0.0f) {
        // Progressive: {next(chunk) → accumulate(chunk)} until the budget is spent (the
        // sampler's set-up, e.g. the Metropolis bootstrap, and the G-buffer count too).
        Timer budget;
        if (renderer) renderer->begin(scene.camera, ro);
        Timer setup;
        std::unique_ptr<sampler::VplStream> stream =
            sampler::make_vpl_stream(sampler_name, scene, accel, lights, scene.camera, settings);
        sampling_seconds += setup.seconds();
        const bool unlit = warn_if_unlit(*stream, scene_path);
        // Progress in tenths of the budget.
        const int64_t tenths = int64_t(std::ceil(time_budget * 10.0f));
        int64_t shown = 0;
        Progress progress("render", tenths, quiet);
        std::vector<light::Vpl> chunk;
        // --oracle: each chunk is gathered at once (VPL light only, unscaled) so that the budget
        // counts the CPU shading too; the emitted radiance is added once at the end.
        reference::GatherOptions g_chunk = g;
        g_chunk.max_depth = 0;
        g_chunk.quiet = true;
        Image sum(width, height);
        const uint64_t first = uint64_t(batch);
        while (!unlit && budget.seconds() < double(time_budget)) {
            const uint64_t work = next_chunk(stream->work_done(), budget.seconds(),
                                             double(time_budget) - budget.seconds(), first);
            chunk.clear();
            Timer sampling;
            stream->next(work, chunk);
            sampling_seconds += sampling.seconds();
            Timer shading;
            if (renderer) {
                renderer->accumulate(chunk);
            } else if (!chunk.empty()) {
                const Image part = reference::gather_vpls(scene, accel, chunk, g_chunk);
                for (int y = 0; y < height; ++y) {
                    for (int x = 0; x < width; ++x)
                        sum.at(x, y) += part.at(x, y);
                }
            }
            shading_seconds += shading.seconds();
            vpl_count += chunk.size();
            progress.set_status(stream->statistics());
            const int64_t now = std::min(tenths, int64_t(budget.seconds() * 10.0));
            progress.advance(now - shown);
            shown = now;
        }
        progress.finish();
        units = stream->work_done();
        statistics = stream->statistics();
        Timer shading;
        if (renderer) {
            image = renderer->resolve(stream->scale());
            t = renderer->timings();
        } else {
            image = reference::gather_vpls(scene, accel, {}, g);  // emitted radiance only
            for (int y = 0; y < height; ++y) {
                for (int x = 0; x < width; ++x)
                    image.at(x, y) += sum.at(x, y) * float(stream->scale());
            }
        }
        shading_seconds += shading.seconds();
    } else {
        std::vector<light::Vpl> vpls;
        Timer sampling;
        if (sampler_name == "mc") {
            // Today's path: the whole run at once, powers divided by N inside the tracer.
            sampler::MonteCarloOptions mc;
            mc.paths = paths;
            mc.seed = seed;
            mc.qmc = qmc;
            mc.per_path = settings.per_path;
            mc.tracer = settings.tracer;
            mc.quiet = quiet;
            vpls = sampler::MonteCarloSampler(scene, accel, lights).generate(mc);
            units = paths;
        } else {
            std::unique_ptr<sampler::VplStream> stream = sampler::make_vpl_stream(
                sampler_name, scene, accel, lights, scene.camera, settings);
            warn_if_unlit(*stream, scene_path);
            stream->next(paths, vpls);
            for (light::Vpl& v : vpls)
                v.power *= float(stream->scale());
            units = stream->work_done();
            statistics = stream->statistics();
        }
        sampling_seconds = sampling.seconds();
        vpl_count = vpls.size();
        Timer shading;
        if (oracle) {
            image = reference::gather_vpls(scene, accel, vpls, g);
        } else {
            Progress progress("render", int64_t(vpls.size()), quiet);
            ro.on_batch = [&progress](size_t count) { progress.advance(int64_t(count)); };
            image = renderer->render(vpls, ro, &t);
            progress.finish();
        }
        shading_seconds = shading.seconds();
    }
    if (context) {
        // MVPL_VALIDATION=1: whatever the layer reported is shown, one line a message.
        for (const std::string& message : context->validation_messages()) {
            std::fprintf(stderr, "mvpl: validation: %s\n", message.c_str());
        }
        char buf[160];
        std::snprintf(buf, sizeof buf,
                      "G-buffer %.1f ms, shadow %.1f ms, shading %.1f ms, %u batches",
                      t.g_buffer_ms, t.shadow_ms, t.shading_ms, t.batches);
        pass_times = buf;
    }
    for (const std::string& out : outputs)
        write_image(image, out, exposure);

    if (!quiet) {
        std::printf(
            "render: %zu VPLs from %llu %s, %dx%d: sampling %.2f s, shading %.2f s (%s), "
            "total %.2f s, %.1f VPL/s%s%s\n",
            vpl_count, static_cast<unsigned long long>(units),
            sampler_name == "mc" ? "paths" : "steps", width, height, sampling_seconds,
            shading_seconds, pass_times.c_str(), total.seconds(),
            double(vpl_count) / std::max(shading_seconds + sampling_seconds, 1e-9),
            statistics.empty() ? "" : "; ", statistics.c_str());
    }
    return 0;
}

}  // namespace mvpl::cli
