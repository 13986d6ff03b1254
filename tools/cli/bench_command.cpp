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
#include "engine/integrator/vpl_integrator.h"
#include "engine/light/chain_options.h"
#include "engine/sampler/monte_carlo_stream.h"
#include "engine/sampler/recorded_vpl_stream.h"
#include "tools/cli/arg_parser.h"
#include "tools/cli/bench_report.h"
#include "tools/cli/bench_runs.h"
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

// What `mvpl bench` was asked.
struct BenchArgs {
    std::string scene_path;
    BenchConfig config;
    uint64_t paths = 256;
    int repeat = 3;
    sampler::MonteCarloOptions mc;
    RendererArgs renderer;
    ManyLightsArgs many_lights;
    std::string json_path;
    bool sweep = false, quiet = false, no_shadows = false;
    CameraArgs camera;
    EnvironmentArgs environment;
    SceneFileArgs scene_file;
};

void add_options(ArgParser& parser, BenchArgs& a) {
    parser.add_positional("SCENE", &a.scene_path, "scene (.gltf, .glb, .ply, .obj)");
    parser.add_resolution("--res", &a.config.width, &a.config.height, "image size");
    parser.add_uint64("--vpls", &a.paths, "light paths to trace, one VPL per bounce");
    parser.add_int("--repeat", &a.repeat, "runs per measurement; medians are reported");
    parser.add_flag("--sweep", &a.sweep,
                    "also render with batch 8..128 × shadow faces 128², 256², 512², and with "
                    "each lever of issue 14 switched (shadow culling, proxy, hemicubes, VPL "
                    "culling, interleave)");
    parser.add_flag("--no-shadows", &a.no_shadows,
                    "every VPL unshadowed: no shadow pass, no cube-map lookups in shading (to "
                    "measure what visibility costs)");
    parser.add_string("--json", &a.json_path, "write the results as JSON to this file", "FILE");
    parser.add_flag("--quiet", &a.quiet, "no progress bar and no table");
    add_renderer_options(parser, a.renderer);
    add_many_lights_options(parser, a.many_lights);
    add_max_depth_option(parser, a.mc.tracer.max_depth);
    add_seed_option(parser, a.mc.seed);
    add_camera_options(parser, a.camera);
    add_environment_options(parser, a.environment);
    add_scene_file_options(parser, a.scene_file);
    add_examples(parser);
}

// The main configuration from the renderer's options.
void configure(BenchArgs& a) {
    BenchConfig& config = a.config;
    const RendererArgs& r = a.renderer;
    config.shadow_resolution = r.shadow_res;
    config.batch = r.batch;
    config.shadow_culling = !r.no_shadow_culling;
    config.shadow_proxy = !r.no_shadow_proxy;
    config.shadow_lod = !r.no_shadow_lod;
    config.backface_culling = !r.no_backface_culling;
    config.jitter = !r.no_jitter;
    config.batches_per_position = r.batches_per_position;
    // The throughput of the levers: interleaving on unless asked otherwise, chains or not (the
    // sweep shows it off); `mvpl render` leaves it off where chains are traced (option_groups.h).
    config.interleave = r.interleave > 0 ? r.interleave : RendererArgs::kDefaultInterleave;
    config.hemicube = !r.no_hemicube;
    config.vpl_culling = !r.no_vpl_culling;
    config.chain_roughness = r.no_chains ? -1.0f : r.chain_roughness;
    config.max_depth = a.mc.tracer.max_depth;
    config.vsl_radius = r.vsl();
    config.many_lights = a.many_lights.options();
    a.mc.paths = a.paths;
}

// --sweep: the batch sizes × shadow resolutions, then each lever switched at the main
// configuration, then (at *devices_sweep) the main configuration with the other device count.
std::vector<BenchConfig> sweep_configs(const BenchConfig& config, size_t* devices_sweep) {
    std::vector<BenchConfig> configs;
    for (const int r : kSweepShadowResolutions) {
        for (const int b : kSweepBatches) {
            BenchConfig c = config;
            c.shadow_resolution = r;
            c.batch = b;
            configs.push_back(c);
        }
    }
    auto with = [&](auto change) {
        BenchConfig c = config;
        change(c);
        configs.push_back(c);
    };
    with([](BenchConfig& c) { c.shadow_culling = !c.shadow_culling; });
    with([](BenchConfig& c) { c.shadow_proxy = !c.shadow_proxy; });
    with([](BenchConfig& c) { c.hemicube = !c.hemicube; });
    with([](BenchConfig& c) { c.vpl_culling = !c.vpl_culling; });
    with([](BenchConfig& c) { c.interleave = c.interleave == 1 ? kSweepInterleave : 1; });
    with([](BenchConfig& c) {
        c.chain_roughness = c.chain_roughness >= 0.0f ? -1.0f : light::kDefaultChainRoughness;
    });
    with([](BenchConfig& c) { c.shadow_lod = !c.shadow_lod; });
    with([](BenchConfig& c) { c.backface_culling = !c.backface_culling; });
    // One device against two (or the other way round): the renderer's devices are known once
    // the context is (RendererArgs::devices_for), and this configuration gets the other count,
    // on an integrator of its own.
    *devices_sweep = configs.size();
    configs.push_back(config);
    return configs;
}

// What the main configuration is compared with: --sweep's, and with row-column sampling every
// VPL shaded (the same VPLs).
std::vector<BenchConfig> compared_configs(const BenchArgs& a, size_t* devices_sweep) {
    std::vector<BenchConfig> configs =
        a.sweep ? sweep_configs(a.config, devices_sweep) : std::vector<BenchConfig>{};
    if (a.config.many_lights.enabled()) {
        BenchConfig every_vpl = a.config;
        every_vpl.many_lights.pool = 0;
        configs.push_back(every_vpl);
    }
    return configs;
}

// One repeat's scene, device and integrators, built from scratch so that start-up is measured
// every repeat too.
struct BenchSetup {
    std::unique_ptr<session::SceneSession> session;
    std::unique_ptr<gpu::Context> context;
    std::unique_ptr<integrator::VplIntegrator> integrator;
    std::unique_ptr<integrator::VplIntegrator> other_devices;  // the sweep's other device count
};

// The start-up times of each repeat.
struct StartupTimes {
    std::vector<double> load_s, bvh_s, context_s, renderer_s;
};

BenchSetup set_up(BenchArgs& a, std::vector<BenchConfig>& sweep, size_t devices_sweep,
                  StartupTimes& times, bool first, cluster::Cluster& ranks) {
    BenchSetup b;
    const float clamp = a.renderer.clamp;
    cluster::together(ranks, [&] {
        b.session = std::make_unique<session::SceneSession>(
            a.scene_path, a.camera.choice, a.environment.choice, a.scene_file.options);
        if (a.renderer.batches_per_position == 0) {
            const int per = int(a.renderer.batches_per_position_for(b.session->scene()));
            a.config.batches_per_position = per;
            for (BenchConfig& c : sweep)
                c.batches_per_position = per;
        }
        times.load_s.push_back(b.session->load_seconds());
        times.bvh_s.push_back(b.session->bvh_seconds());
        if (first && ranks.root()) b.session->warn_if_no_light("nothing to bench");
        Timer t;
        b.context = std::make_unique<gpu::Context>();
        times.context_s.push_back(t.seconds());
        const uint32_t devices = a.renderer.devices_for(b.context->device_info());
        a.config.devices = int(devices);
        for (size_t i = 0; i < sweep.size(); ++i)
            sweep[i].devices = i == devices_sweep ? (devices == 1 ? 2 : 1) : int(devices);
    });
    const scene::Camera& camera = b.session->scene().camera;
    Timer t;
    // With the BVH: specular chains, where the scene has glossy surfaces. The first begin()
    // builds the passes: pipelines and shader compilation belong to start-up, not to the
    // throughput of later renders.
    b.integrator = std::make_unique<integrator::VplIntegrator>(b.session->view(), b.context.get(),
                                                               uint32_t(a.config.devices), &ranks);
    cluster::together(ranks, [&] {
        b.integrator->renderer()->begin(camera, render_options(a.config, clamp, !a.no_shadows));
    });
    times.renderer_s.push_back(t.seconds());
    if (devices_sweep < sweep.size()) {
        const BenchConfig& c = sweep[devices_sweep];
        b.other_devices = std::make_unique<integrator::VplIntegrator>(
            b.session->view(), b.context.get(), uint32_t(c.devices), &ranks);
        cluster::together(ranks, [&] {
            b.other_devices->renderer()->begin(camera, render_options(c, clamp, !a.no_shadows));
        });
    }
    return b;
}

// Writes the JSON (opened before the runs) and prints the table, on rank 0.
void report_results(const BenchArgs& a, const BenchReport& report, std::ofstream& json_out,
                    cluster::Cluster& ranks) {
    cluster::together(ranks, [&] {
        if (json_out.is_open()) {
            json_out << bench_json(report);
            json_out.close();
            if (!json_out) throw InputError(a.json_path, "cannot write the benchmark JSON");
        }
        if (!a.quiet) std::fputs(bench_table(report).c_str(), stdout);
    });
}

}  // namespace

int run_bench(const Args& args) {
    BenchArgs a;
    ArgParser parser("bench",
                     "Measures VPL throughput on SCENE: light-path generation, the shadow and\n"
                     "shading passes (GPU timestamps), end to end, start-up and peak memory.\n"
                     "Every number is the median of --repeat runs.");
    add_options(parser, a);
    cluster::Cluster& ranks = cluster::world();
    bool parsed = false;
    cluster::together(ranks, [&] { parsed = parser.parse(args); });
    if (!parsed) return 0;
    if (!ranks.root()) a.quiet = true;
    configure(a);
    std::ofstream json_out;
    cluster::together(ranks, [&] {
        if (a.paths < 1 || a.paths > (uint64_t(1) << 24))
            throw UsageError("bench: --vpls must be in 1..2^24");
        if (a.repeat < 1 || a.repeat > 1000) throw UsageError("bench: --repeat must be in 1..1000");
        if (!a.json_path.empty() && ranks.root()) json_out = open_output(a.json_path);
    });
    size_t devices_sweep = SIZE_MAX;
    std::vector<BenchConfig> sweep = compared_configs(a, &devices_sweep);

    BenchReport report;
    report.scene = a.scene_path;
    report.repeat = a.repeat;
    report.shadows = !a.no_shadows;
    report.paths = a.paths;
    StartupTimes startup;
    std::vector<double> sampling_s;
    std::vector<RenderSample> main_samples;
    std::vector<std::vector<RenderSample>> sweep_samples(sweep.size());
    Progress progress("bench", int64_t(a.repeat) * int64_t(1 + sweep.size()), a.quiet);
    const float clamp = a.renderer.clamp;
    for (int k = 0; k < a.repeat; ++k) {
        BenchSetup b = set_up(a, sweep, devices_sweep, startup, k == 0, ranks);
        cluster::together(ranks, [] {});
        Timer t;
        const sampler::VplRecording vpls = sample(*b.session, a.mc, ranks);
        sampling_s.push_back(t.seconds());
        report.vpls = vpls.vpls_total;
        report.triangles = b.session->scene().triangle_count();
        report.device = b.context->device_info().name;
        const integrator::SceneView view = b.session->view();
        main_samples.push_back(render_once(*b.integrator, view, vpls,
                                           estimate_of(a.config, clamp, !a.no_shadows), ranks));
        progress.advance();
        for (size_t i = 0; i < sweep.size(); ++i) {
            integrator::VplIntegrator& r = i == devices_sweep ? *b.other_devices : *b.integrator;
            sweep_samples[i].push_back(
                render_once(r, view, vpls, estimate_of(sweep[i], clamp, !a.no_shadows), ranks));
            progress.advance();
        }
        report.peak_device_bytes =
            std::max(report.peak_device_bytes, b.integrator->renderer()->peak_device_bytes());
    }
    progress.finish();

    report.scene_load_s = median(startup.load_s);
    report.bvh_build_s = median(startup.bvh_s);
    report.context_s = median(startup.context_s);
    report.renderer_s = median(startup.renderer_s);
    report.sampling_s = median(sampling_s);
    report.main = summarise(a.config, main_samples, report.vpls, report.sampling_s);
    for (size_t i = 0; i < sweep.size(); ++i)
        report.sweep.push_back(
            summarise(sweep[i], sweep_samples[i], report.vpls, report.sampling_s));
    report.peak_host_bytes = peak_host_bytes();
    report.ranks = ranks.size();
    report_results(a, report, json_out, ranks);
    return 0;
}

}  // namespace mvpl::cli
