// `mvpl render`: VPLs from a sampler, shaded on the GPU (or by the CPU oracle with --oracle).
// This file declares the command's options and wires them; render_runs.h forms the image.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include "engine/cluster/cluster.h"

#include "engine/core/error.h"
#include "engine/core/image.h"
#include "engine/core/interrupt.h"
#include "engine/core/subpixel.h"
#include "engine/core/timer.h"
#include "engine/gpu/context.h"
#include "engine/gpu/device_info.h"
#include "engine/sampler/metropolis_budget.h"
#include "tools/cli/arg_parser.h"
#include "tools/cli/commands.h"
#include "tools/cli/device_choice.h"
#include "tools/cli/option_groups.h"
#include "tools/cli/output_check.h"
#include "tools/cli/render_runs.h"

namespace mvpl::cli {

namespace {

// Everything `mvpl render` reads from its command line.
struct RenderArgs {
    std::string scene_path;
    CameraArgs camera;
    EnvironmentArgs environment;
    SceneFileArgs scene_file;
    std::string sampler_name = "mc";
    std::string per_path;  // empty: each sampler's default
    uint64_t paths = 1024;
    int width = 256, height = 256;
    RendererArgs renderer;
    std::vector<std::string> outputs;
    float exposure = 0.0f;
    int device = -1;
    bool qmc = false, random_paths = false, oracle = false, quiet = false;
    CompensationArgs compensation;
    bool no_caustics = false;
    ManyLightsArgs many_lights;
    std::string dump_shaders;
    bool no_shader_cache = false;
    float time_budget = 0.0f;
    sampler::SamplerSettings settings;
};

void add_options(ArgParser& parser, RenderArgs& a) {
    parser.add_positional("SCENE", &a.scene_path, "scene (.gltf, .glb, .xml, .ply, .obj)");
    parser.add_uint64("--vpls", &a.paths,
                      "mc: light paths to trace, each leaves one VPL per bounce (--vpl-per-path "
                      "all) or one; metropolis: chain steps");
    parser.add_float("--time-budget", &a.time_budget,
                     "seconds of sampling + shading: render as many VPLs as fit (overrides --vpls)",
                     "SEC");
    parser.add_flag("--qmc", &a.qmc,
                    "mc: Halton primary samples, randomly shifted by the seed (the default)");
    parser.add_flag("--random-paths", &a.random_paths,
                    "mc: random primary samples instead of Halton ones");
    parser.add_string("--vpl-per-path", &a.per_path,
                      "VPLs a light path leaves: all (one per bounce) or one (the seed paper's "
                      "choice); default all for mc, one for metropolis",
                      "all|one");
    parser.add_resolution("--res", &a.width, &a.height, "image size");
    parser.add_strings("-o", &a.outputs, "output image, .exr or .png", "FILE");
    parser.add_float("--exposure", &a.exposure, "PNG exposure in stops");
    parser.add_flag("--oracle", &a.oracle,
                    "shade on the CPU with exact visibility instead of the GPU");
    parser.add_flag("--quiet", &a.quiet, "no progress bar and no summary line");
    parser.add_string("--dump-shaders", &a.dump_shaders,
                      "write the GLSL generated for this scene, every stage, into DIR", "DIR");
    parser.add_flag("--no-shader-cache", &a.no_shader_cache,
                    "compile every shader; neither read nor write the SPIR-V cache");
    add_sampler_option(parser, a.sampler_name);
    add_metropolis_options(parser, a.settings);
    add_renderer_options(parser, a.renderer);
    add_compensation_options(parser, a.compensation);
    add_caustics_option(parser, a.no_caustics);
    add_many_lights_options(parser, a.many_lights);
    add_max_depth_option(parser, a.settings.tracer.max_depth);
    add_seed_option(parser, a.settings.seed);
    add_camera_options(parser, a.camera);
    add_environment_options(parser, a.environment);
    add_scene_file_options(parser, a.scene_file);
    add_device_option(parser, a.device,
                      "Vulkan device index (see mvpl info), -1 = default; under mpirun "
                      "local-rank: by the rank's place on its machine",
                      "N|local-rank");
    parser.add_example("mvpl render assets/cornell-box/cbox.gltf --res 512x512 -o cbox.png",
                       "the Cornell box from 1024 light paths' VPLs, as an sRGB PNG");
    parser.add_example("mvpl render assets/glossy/glossy.gltf --time-budget 10 -o glossy.exr",
                       "as many VPLs as fit in 10 seconds, as a linear EXR");
    parser.add_example("mvpl render assets/two-room/two-room.gltf --sampler metropolis --vpls 4096",
                       "VPLs from 4096 Metropolis chain steps, placed where they light what the "
                       "camera sees; the image goes to render.exr");
    parser.add_check([&a] {
        if (!a.per_path.empty() && a.per_path != "all" && a.per_path != "one")
            throw UsageError("render: --vpl-per-path must be all or one");
        if (a.paths < 1 || a.paths > (uint64_t(1) << 32))
            throw UsageError("render: --vpls must be in 1..2^32");
        if (!(a.time_budget >= 0.0f && a.time_budget <= 1e6f))
            throw UsageError("render: --time-budget must be in [0, 1e6] seconds");
    });
}

RenderJob make_job(RenderArgs& a, const session::SceneSession& session) {
    RenderJob job;
    job.session = &session;
    job.quiet = a.quiet;
    integrator::Estimate& e = job.estimate;
    e.sampler = a.sampler_name;
    sampler::SamplerSettings& s = e.sampling;
    s = a.settings;
    if (a.qmc && a.random_paths)
        throw UsageError("render: --qmc and --random-paths exclude each other");
    if (a.random_paths) s.qmc = false;
    s.per_path = a.per_path == "one" ? sampler::VplsPerPath::One : sampler::VplsPerPath::All;
    s.metropolis_per_path =
        a.per_path == "all" ? sampler::VplsPerPath::All : sampler::VplsPerPath::One;
    const int max_depth = s.tracer.max_depth;
    render::RenderOptions& ro = e.render;
    ro.width = uint32_t(a.width);
    ro.height = uint32_t(a.height);
    a.renderer.apply(ro);
    ro.dump_shaders = a.dump_shaders;
    ro.shader_cache = !a.no_shader_cache;
    ro.surface_vpls = max_depth < 0 || max_depth >= 3;  // surface VPLs light depth ≥ 3
    ro.subpixel_rotation = subpixel_rotation(s.seed);   // the seed varies the positions too
    ro.chains.max_depth = max_depth;
    ro.interleave = a.renderer.interleave_for(session.scene(), ro.chains, ro.width, ro.height);
    ro.batches_per_position = a.renderer.batches_per_position_for(session.scene());
    ro.chain_seed = s.seed;
    e.compensate = a.compensation.enabled();
    e.compensation_passes = uint32_t(a.compensation.spp);
    // Paired with the chains: what they continue leaves no VPL, the caustic tracer carries it.
    e.caustics = !a.no_caustics;
    e.many_lights = a.many_lights.options();
    return job;
}

}  // namespace

int run_render(const Args& args) {
    // Under mpirun every rank runs this with the same arguments (engine/cluster): each loads the
    // scene and its device and renders its share; rank 0 alone writes and prints. Whatever fails
    // on one rank is met by the others at the next agreement point (cluster::together).
    cluster::Cluster& ranks = cluster::world();
    RenderArgs a;
    // SIGINT, SIGTERM: stop after the chunk in flight and write what has converged; a second
    // signal exits at once (engine/core/interrupt.h). Commands that do not poll keep the default.
    install_interrupt_handlers();
    ArgParser parser(
        "render",
        "Renders SCENE with virtual point lights: a sampler traces light paths on the CPU\n"
        "and leaves VPLs; the GPU shades them in batches with cube-map shadows.\n"
        "Under mpirun, the ranks share the work and rank 0 writes the image.");
    add_options(parser, a);
    bool parsed = false, defaulted = false;
    Timer total;
    std::unique_ptr<session::SceneSession> session;
    std::unique_ptr<gpu::Context> context;
    std::unique_ptr<render::VplRenderer> renderer;
    cluster::together(ranks, [&] {
        parsed = parser.parse(with_local_rank_device(args));
        if (!parsed) return;
        if (!a.oracle) check_device("render", a.device);
        if (ranks.size() > 1 && a.oracle)
            throw UsageError("render: --oracle runs on one process, not under mpirun");
        a.outputs = outputs_or(a.outputs, "render.exr", defaulted);
        if (ranks.root()) check_outputs(a.outputs);
        if (!ranks.root()) a.quiet = true;
        total.reset();
        session = std::make_unique<session::SceneSession>(
            a.scene_path, a.camera.choice, a.environment.choice, a.scene_file.options);
        apply_scene_defaults(parser, session->scene(), &a.settings.tracer.max_depth, &a.width,
                             &a.height);
        session->warn_if_no_light("the image shows emitters only");
        if (!a.oracle) {
            gpu::ContextOptions co;
            co.device_index = a.device;
            context = std::make_unique<gpu::Context>(co);
            renderer = std::make_unique<render::VplRenderer>(
                *context, session->scene(), &session->accel(),
                a.renderer.devices_for(context->device_info()));
        }
    });
    if (!parsed) return 0;
    if (a.sampler_name == "metropolis") {
        sampler::scale_pool_for_budget(a.settings, double(a.time_budget), parser.given("--chains"),
                                       parser.given("--bootstrap"));
    }
    RenderJob job = make_job(a, *session);
    job.renderer = renderer.get();
    if (ranks.size() > 1) job.cluster = &ranks;

    const RenderOutcome result =
        a.time_budget > 0.0f ? render_for(job, double(a.time_budget)) : render_once(job, a.paths);
    // Rank 0 writes; the others wait for it, so that all exit with its status.
    cluster::together(ranks, [&] {
        if (context) {
            // MVPL_VALIDATION=1: whatever the layer reported is shown, one line a message.
            for (const std::string& message : context->validation_messages())
                std::fprintf(stderr, "mvpl: validation: %s\n", message.c_str());
        }
        if (!ranks.root()) return;
        session->warn_if_black(result.image);
        write_images(result.image, a.outputs, a.exposure);
        say_written("render", a.outputs, defaulted, a.quiet);
        if (!a.quiet) std::fputs(summary_line(job, result, total.seconds()).c_str(), stdout);
    });
    return 0;
}

}  // namespace mvpl::cli
