// `mvpl bench`: VPL throughput. Light-path generation on the CPU, the shadow and shading passes
// on the GPU (timestamp queries), end to end, start-up and peak memory; every number is the
// median of --repeat runs, because a shared machine is noisy. Under mpirun (engine/cluster) the
// ranks share the light paths as `mvpl render` does and the numbers are the job's: VPLs of all
// ranks, wall times from a meeting of all ranks to rank 0's resolved image, GPU pass times summed
// over the ranks (start-up and memory are rank 0's).
#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "engine/cluster/cluster.h"
#include "engine/core/error.h"
#include "engine/core/progress.h"
#include "engine/core/timer.h"
#include "engine/gpu/context.h"
#include "engine/gpu/memory.h"
#include "engine/light/chain_options.h"
#include "engine/render/vpl_renderer.h"
#include "engine/sampler/monte_carlo_sampler.h"
#include "engine/sampler/monte_carlo_stream.h"
#include "tools/cli/arg_parser.h"
#include "tools/cli/bench_report.h"
#include "tools/cli/commands.h"
#include "tools/cli/option_groups.h"
#include "tools/session/scene_session.h"

namespace mvpl::cli {

namespace {

// --sweep: batch sizes × shadow face sides, around the defaults (32, 256).
constexpr int kSweepBatches[] = {8, 16, 32, 64, 128};
constexpr int kSweepShadowResolutions[] = {128, 256, 512};
// The interleave the sweep tries when the main configuration has none.
constexpr int kSweepInterleave = 4;

render::RenderOptions render_options(const BenchConfig& c, float clamp, bool shadows) {
    render::RenderOptions ro;
    ro.width = uint32_t(c.width);
    ro.height = uint32_t(c.height);
    ro.shadow_resolution = uint32_t(c.shadow_resolution);
    ro.batch = uint32_t(c.batch);
    ro.jitter = c.jitter;
    ro.batches_per_position = uint32_t(std::max(c.batches_per_position, 1));
    ro.clamp = clamp;
    ro.shadows = shadows;
    ro.shadow_culling = c.shadow_culling;
    ro.shadow_proxy = c.shadow_proxy;
    ro.shadow_lod = c.shadow_lod;
    ro.backface_culling = c.backface_culling;
    ro.interleave = uint32_t(c.interleave);
    ro.hemicube = c.hemicube;
    ro.vpl_culling = c.vpl_culling;
    ro.chains.max_roughness = c.chain_roughness;
    ro.chains.max_depth = c.max_depth;
    ro.vsl_radius = c.vsl_radius;
    return ro;
}

// This rank's VPLs (all of them on one process), each one's index in the one-process order
// (empty on one process), and the job's VPL count.
struct Share {
    light::VplSet vpls;
    std::vector<uint64_t> index;
    uint64_t total = 0;
};

Share sample(const session::SceneSession& session, const sampler::MonteCarloOptions& mc,
             cluster::Cluster& ranks) {
    Share share;
    if (ranks.size() == 1) {
        share.vpls = sampler::MonteCarloSampler(session.scene(), session.accel(), session.lights())
                         .generate(mc);
    } else {
        sampler::MonteCarloOptions o = mc;
        o.cluster = &ranks;
        sampler::MonteCarloStream stream(session.scene(), session.accel(), session.lights(), o);
        stream.next(mc.paths, share.vpls.vpls);
        share.vpls.scale = stream.scale();
        share.index.assign(stream.last_index().begin(), stream.last_index().end());
    }
    std::vector<uint64_t> total(1, share.vpls.vpls.size());
    if (ranks.size() > 1) ranks.sum_all(total);
    share.total = total[0];
    return share;
}

// One progressive render of all VPLs; over ranks, from a meeting of all to rank 0's image.
RenderSample render_once(render::VplRenderer& renderer, const scene::Camera& camera,
                         const Share& share, const BenchConfig& config, float clamp, bool shadows,
                         cluster::Cluster& ranks) {
    cluster::together(ranks, [] {});
    Timer wall;
    Image image;
    cluster::together(ranks, [&] {
        renderer.begin(camera, render_options(config, clamp, shadows));
        renderer.accumulate(share.vpls.vpls, share.index);
        // The read-back costs too.
        image = ranks.size() == 1 ? renderer.resolve(share.vpls.scale) : renderer.contributions();
    });
    if (ranks.size() > 1) {
        ranks.sum_to_root(image.channels());
        cluster::together(ranks, [&] {
            if (ranks.root()) image = renderer.resolve(share.vpls.scale, image, share.total);
        });
    }
    RenderSample s;
    s.wall_s = wall.seconds();
    const render::RenderTimings& t = renderer.timings();
    s.g_buffer_ms = t.g_buffer_ms;
    s.shadow_ms = t.shadow_ms;
    s.shading_ms = t.shading_ms;
    s.batches = t.batches;
    s.shadow_triangles = t.shadow_triangles;
    s.shadow_front_only_triangles = t.shadow_front_only_triangles;
    s.shadow_texels = t.shadow_texels;
    s.culled_vpls = t.culled_vpls;
    s.g_buffers = t.g_buffers;
    s.chain_ms = t.chain_ms;
    s.chain_rays = t.chain_rays;
    if (ranks.size() > 1) {
        // GPU time and work summed over the ranks, so that per VPL they are the job's cost.
        std::vector<double> sums{s.g_buffer_ms,
                                 s.shadow_ms,
                                 s.shading_ms,
                                 double(s.batches),
                                 double(s.shadow_triangles),
                                 double(s.g_buffers),
                                 double(s.shadow_front_only_triangles)};
        ranks.sum_all(sums);
        s.g_buffer_ms = sums[0];
        s.shadow_ms = sums[1];
        s.shading_ms = sums[2];
        s.batches = uint32_t(sums[3]);
        s.shadow_triangles = uint64_t(sums[4]);
        s.g_buffers = uint32_t(sums[5]);
        s.shadow_front_only_triangles = uint64_t(sums[6]);
    }
    return s;
}

uint64_t peak_host_bytes() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return uint64_t(usage.ru_maxrss) * 1024;  // Linux reports KiB
}

// Opened before the benchmark runs, so that a mistyped path fails at once, not after minutes.
std::ofstream open_output(const std::string& path) {
    std::ofstream out(path, std::ios::binary);
    if (!out) throw InputError(path, "cannot write the benchmark JSON");
    return out;
}

void add_examples(ArgParser& parser) {
    parser.add_example("mvpl bench assets/cornell-box/cbox.gltf --res 512x512 --shadow-res 256",
                       "the Cornell box at 512², 256² shadow faces: pass times and VPL/s");
    parser.add_example("mvpl bench assets/two-room/two-room.gltf --sweep --json rooms.json",
                       "also each batch size, shadow resolution and lever, written as JSON");
    parser.add_example(
        "mvpl bench assets/glossy/glossy.gltf --res 512x512 --repeat 1 --no-specular-chains",
        "the glossy scene's throughput without its specular chains");
}

}  // namespace

int run_bench(const Args& args) {
    std::string scene_path;
    BenchConfig config;
    uint64_t paths = 256;
    int repeat = 3;
    sampler::MonteCarloOptions mc;
    RendererArgs renderer_args;
    std::string json_path;
    bool sweep = false, quiet = false, no_shadows = false;
    ArgParser parser("bench",
                     "Measures VPL throughput on SCENE: light-path generation, the shadow and\n"
                     "shading passes (GPU timestamps), end to end, start-up and peak memory.\n"
                     "Every number is the median of --repeat runs.");
    parser.add_positional("SCENE", &scene_path, "scene (.gltf, .glb, .ply, .obj)");
    parser.add_resolution("--res", &config.width, &config.height, "image size");
    parser.add_uint64("--vpls", &paths, "light paths to trace, one VPL per bounce");
    parser.add_int("--repeat", &repeat, "runs per measurement; medians are reported");
    parser.add_flag("--sweep", &sweep,
                    "also render with batch 8..128 × shadow faces 128², 256², 512², and with "
                    "each lever of issue 14 switched (shadow culling, proxy, hemicubes, VPL "
                    "culling, interleave)");
    parser.add_flag("--no-shadows", &no_shadows,
                    "every VPL unshadowed: no shadow pass, no cube-map lookups in shading (to "
                    "measure what visibility costs)");
    parser.add_string("--json", &json_path, "write the results as JSON to this file", "FILE");
    parser.add_flag("--quiet", &quiet, "no progress bar and no table");
    add_renderer_options(parser, renderer_args);
    add_max_depth_option(parser, mc.tracer.max_depth);
    add_seed_option(parser, mc.seed);
    CameraArgs camera;
    add_camera_options(parser, camera);
    EnvironmentArgs environment;
    add_environment_options(parser, environment);
    SceneFileArgs scene_file;
    add_scene_file_options(parser, scene_file);
    add_examples(parser);
    cluster::Cluster& ranks = cluster::world();
    bool parsed = false;
    cluster::together(ranks, [&] { parsed = parser.parse(args); });
    if (!parsed) return 0;
    if (!ranks.root()) quiet = true;
    config.shadow_resolution = renderer_args.shadow_res;
    config.batch = renderer_args.batch;
    config.shadow_culling = !renderer_args.no_shadow_culling;
    config.shadow_proxy = !renderer_args.no_shadow_proxy;
    config.shadow_lod = !renderer_args.no_shadow_lod;
    config.backface_culling = !renderer_args.no_backface_culling;
    config.jitter = !renderer_args.no_jitter;
    config.batches_per_position = renderer_args.batches_per_position;
    // The throughput of the levers: interleaving on unless asked otherwise, chains or not (the
    // sweep shows it off); `mvpl render` leaves it off where chains are traced (option_groups.h).
    config.interleave =
        renderer_args.interleave > 0 ? renderer_args.interleave : RendererArgs::kDefaultInterleave;
    config.hemicube = !renderer_args.no_hemicube;
    config.vpl_culling = !renderer_args.no_vpl_culling;
    config.chain_roughness = renderer_args.no_chains ? -1.0f : renderer_args.chain_roughness;
    config.max_depth = mc.tracer.max_depth;
    config.vsl_radius = renderer_args.vsl();
    const float clamp = renderer_args.clamp;
    mc.paths = paths;
    std::ofstream json_out;
    cluster::together(ranks, [&] {
        if (paths < 1 || paths > (uint64_t(1) << 24))
            throw UsageError("bench: --vpls must be in 1..2^24");
        if (repeat < 1 || repeat > 1000) throw UsageError("bench: --repeat must be in 1..1000");
        if (!json_path.empty() && ranks.root()) json_out = open_output(json_path);
    });

    std::vector<BenchConfig> sweep_configs;
    size_t devices_sweep = SIZE_MAX;  // the sweep's configuration with the other device count
    if (sweep) {
        for (const int r : kSweepShadowResolutions) {
            for (const int b : kSweepBatches) {
                BenchConfig c = config;
                c.shadow_resolution = r;
                c.batch = b;
                sweep_configs.push_back(c);
            }
        }
        // Each lever on and off at the main configuration.
        BenchConfig c = config;
        c.shadow_culling = !config.shadow_culling;
        sweep_configs.push_back(c);
        c = config;
        c.shadow_proxy = !config.shadow_proxy;
        sweep_configs.push_back(c);
        c = config;
        c.hemicube = !config.hemicube;
        sweep_configs.push_back(c);
        c = config;
        c.vpl_culling = !config.vpl_culling;
        sweep_configs.push_back(c);
        c = config;
        c.interleave = config.interleave == 1 ? kSweepInterleave : 1;
        sweep_configs.push_back(c);
        c = config;
        c.chain_roughness = config.chain_roughness >= 0.0f ? -1.0f : light::kDefaultChainRoughness;
        sweep_configs.push_back(c);
        c = config;
        c.shadow_lod = !config.shadow_lod;
        sweep_configs.push_back(c);
        c = config;
        c.backface_culling = !config.backface_culling;
        sweep_configs.push_back(c);
        // One device against two (or the other way round): the renderer's devices are known
        // once the context is (RendererArgs::devices_for), and this configuration gets the other
        // count, on a renderer of its own.
        devices_sweep = sweep_configs.size();
        sweep_configs.push_back(config);
    }

    BenchReport report;
    report.scene = scene_path;
    report.repeat = repeat;
    report.shadows = !no_shadows;
    report.paths = paths;
    std::vector<double> load_s, bvh_s, context_s, renderer_s, sampling_s;
    std::vector<RenderSample> main_samples;
    std::vector<std::vector<RenderSample>> sweep_samples(sweep_configs.size());
    Progress progress("bench", int64_t(repeat) * int64_t(1 + sweep_configs.size()), quiet);
    for (int k = 0; k < repeat; ++k) {
        // Everything from scratch each repeat, so that start-up is measured K times too.
        std::unique_ptr<session::SceneSession> session;
        std::unique_ptr<gpu::Context> context;
        std::unique_ptr<render::VplRenderer> renderer;
        std::unique_ptr<render::VplRenderer> other_devices;  // the sweep's other device count
        cluster::together(ranks, [&] {
            session = std::make_unique<session::SceneSession>(
                scene_path, camera.choice, environment.choice, scene_file.options);
            if (renderer_args.batches_per_position == 0) {
                const uint32_t b = renderer_args.batches_per_position_for(session->scene());
                config.batches_per_position = int(b);
                for (BenchConfig& c : sweep_configs)
                    c.batches_per_position = int(b);
            }
            load_s.push_back(session->load_seconds());
            bvh_s.push_back(session->bvh_seconds());
            if (k == 0 && ranks.root()) session->warn_if_no_light("nothing to bench");
            Timer t;
            context = std::make_unique<gpu::Context>();
            context_s.push_back(t.seconds());
            t.reset();
            // With the BVH: specular chains, where the scene has glossy surfaces.
            const uint32_t devices = renderer_args.devices_for(context->device_info());
            config.devices = int(devices);
            for (size_t i = 0; i < sweep_configs.size(); ++i)
                sweep_configs[i].devices = i == devices_sweep ? (devices == 1 ? 2 : 1) : devices;
            renderer = std::make_unique<render::VplRenderer>(*context, session->scene(),
                                                             &session->accel(), devices);
            // The first begin() builds the passes: pipelines and shader compilation belong to
            // start-up, not to the throughput of later renders.
            renderer->begin(session->scene().camera, render_options(config, clamp, !no_shadows));
            renderer_s.push_back(t.seconds());
            if (devices_sweep < sweep_configs.size()) {
                const BenchConfig& c = sweep_configs[devices_sweep];
                other_devices = std::make_unique<render::VplRenderer>(
                    *context, session->scene(), &session->accel(), uint32_t(c.devices));
                other_devices->begin(session->scene().camera,
                                     render_options(c, clamp, !no_shadows));
            }
        });
        const scene::Scene& scene = session->scene();

        cluster::together(ranks, [] {});
        Timer t;
        const Share vpls = sample(*session, mc, ranks);
        sampling_s.push_back(t.seconds());
        report.vpls = vpls.total;
        report.triangles = scene.triangle_count();
        report.device = context->device_info().name;

        main_samples.push_back(
            render_once(*renderer, scene.camera, vpls, config, clamp, !no_shadows, ranks));
        progress.advance();
        for (size_t i = 0; i < sweep_configs.size(); ++i) {
            render::VplRenderer& r = i == devices_sweep ? *other_devices : *renderer;
            sweep_samples[i].push_back(
                render_once(r, scene.camera, vpls, sweep_configs[i], clamp, !no_shadows, ranks));
            progress.advance();
        }
        report.peak_device_bytes =
            std::max(report.peak_device_bytes, renderer->peak_device_bytes());
    }
    progress.finish();

    report.scene_load_s = median(load_s);
    report.bvh_build_s = median(bvh_s);
    report.context_s = median(context_s);
    report.renderer_s = median(renderer_s);
    report.sampling_s = median(sampling_s);
    report.main = summarise(config, main_samples, report.vpls, report.sampling_s);
    for (size_t i = 0; i < sweep_configs.size(); ++i) {
        report.sweep.push_back(
            summarise(sweep_configs[i], sweep_samples[i], report.vpls, report.sampling_s));
    }
    report.peak_host_bytes = peak_host_bytes();

    report.ranks = ranks.size();
    cluster::together(ranks, [&] {
        if (json_out.is_open()) {
            json_out << bench_json(report);
            json_out.close();
            if (!json_out) throw InputError(json_path, "cannot write the benchmark JSON");
        }
        if (!quiet) std::fputs(bench_table(report).c_str(), stdout);
    });
    return 0;
}

}  // namespace mvpl::cli
