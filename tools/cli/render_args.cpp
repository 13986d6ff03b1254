#include "tools/cli/render_args.h"
#include "tools/cli/exr_outputs.h"

#include "engine/core/error.h"
#include "engine/core/subpixel.h"
#include "engine/sampler/metropolis_budget.h"

namespace mvpl::cli {

void add_render_options(ArgParser& parser, RenderArgs& a) {
    parser.add_positional("SCENE", &a.scene_path, "scene (.gltf, .glb, .xml, .ply, .obj)");
    parser.add_uint64("--vpls", &a.paths,
                      "mc: light paths to trace, each leaves one VPL per bounce (--vpl-per-path "
                      "all) or one; metropolis: chain steps");
    parser.add_float("--time-budget", &a.time_budget,
                     "seconds of sampling + shading: render as many VPLs as fit (overrides --vpls)",
                     "SEC");
    add_write_every_option(parser, a.write_every, "render");
    parser.add_flag("--qmc", &a.qmc,
                    "mc: Halton primary samples, randomly shifted by the seed (the default)");
    parser.add_flag("--random-paths", &a.random_paths,
                    "mc: random primary samples instead of Halton ones");
    add_vpl_per_path_option(parser, a.per_path);
    parser.add_resolution("--res", &a.width, &a.height, "image size");
    parser.add_strings("-o", &a.outputs, "output image, .exr or .png", "FILE");
    parser.add_float("--exposure", &a.exposure, "PNG exposure in stops");
    add_aov_option(parser, &a.aovs, &a.outputs);
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
        if (a.paths < 1 || a.paths > (uint64_t(1) << 32))
            throw UsageError("render: --vpls must be in 1..2^32");
        if (!(a.time_budget >= 0.0f && a.time_budget <= 1e6f))
            throw UsageError("render: --time-budget must be in [0, 1e6] seconds");
    });
}

integrator::Estimate render_estimate(const ArgParser& parser, RenderArgs& a,
                                     const scene::Scene& scene, bool cpu_device) {
    if (a.sampler_name == "metropolis") {
        sampler::scale_pool_for_budget(a.settings, double(a.time_budget), parser.given("--chains"),
                                       parser.given("--bootstrap"));
    }
    integrator::Estimate e;
    e.sampler = a.sampler_name;
    sampler::SamplerSettings& s = e.sampling;
    s = a.settings;
    if (a.qmc && a.random_paths)
        throw UsageError("render: --qmc and --random-paths exclude each other");
    if (a.random_paths) s.qmc = false;
    apply_vpl_per_path(a.per_path, s);
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
    ro.interleave = a.renderer.interleave_for(scene, ro.chains, ro.width, ro.height);
    ro.batches_per_position = a.renderer.batches_per_position_for(scene);
    ro.chain_seed = s.seed;
    e.compensate = a.compensation.enabled();
    e.compensation_passes = uint32_t(a.compensation.spp);
    // Paired with the chains: what they continue leaves no VPL, the caustic tracer carries it.
    e.caustics = !a.no_caustics;
    e.many_lights =
        a.many_lights.options_for(scene, a.sampler_name, double(a.time_budget), cpu_device);
    return e;
}

}  // namespace mvpl::cli
