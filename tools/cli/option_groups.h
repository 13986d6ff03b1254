#pragma once
// The options that several `mvpl` commands share, each declared once: its flag, its help, its
// default (read from the struct the option configures, never restated here) and its range check
// (run by ArgParser after parsing). Commands register the groups they take and only wire the
// values (pbrt-v4's cmd/ over its render set-up is the model).
#include <cstdint>
#include <string>

#include "engine/gpu/device_info.h"
#include "engine/manylights/automatic_pool.h"
#include "engine/manylights/row_column_options.h"
#include "engine/render/vpl_renderer.h"
#include "engine/sampler/sampler_factory.h"
#include "engine/scene/camera_choice.h"
#include "engine/scene/scene_loader.h"
#include "tools/cli/arg_parser.h"
#include "tools/session/scene_session.h"

namespace mvpl::cli {

// --shadow-res, --batch, --clamp, --vsl-radius, --no-vsl, --no-jitter, --no-shadow-culling,
// --no-shadow-proxy, --no-hemicube, --no-vpl-culling, --interleave, --devices: the GPU
// renderer's (render::RenderOptions), as ints and flags for the parser.
struct RendererArgs {
    int shadow_res = int(render::RenderOptions{}.shadow_resolution);
    int batch = int(render::RenderOptions{}.batch);
    float clamp = render::RenderOptions{}.clamp;
    float vsl_radius = render::RenderOptions{}.vsl_radius;
    bool no_vsl = false;
    bool no_jitter = !render::RenderOptions{}.jitter;
    bool no_shadow_culling = false;
    bool no_shadow_proxy = false;
    bool no_shadow_lod = false;
    bool no_backface_culling = false;
    float chain_roughness = light::kDefaultChainRoughness;
    bool no_chains = false;
    int chain_samples = light::kDefaultChainEmissionSamples;
    bool no_hemicube = false;
    bool no_vpl_culling = false;
    // The command line interleaves (K = 2) by default, where RenderOptions (which the tests set
    // up) does not: shading is most of a render at the resolutions users ask for, and K = 2
    // halves it for ≤ 1.1× the error at equal VPL count (docs/results.md, "Interleaved sampling").
    // 0 (the default): kDefaultInterleave, but 1 where the scene's specular chains are traced
    // (interleave_for): on assets/glossy at 160×120 interleaving costs chained pixels more than
    // it saves, 1.1–1.65× the error at equal time (docs/results.md, "Interleaving with chains");
    // and 1 for images of fewer than kInterleaveMinPixels: there shading is a small share of a
    // render, while the filter's K-pixel window is a large share of the image's features (on
    // the two-room scene at 128² it blurred the lit floor patch's rim 1.5–3.5× too bright, half
    // of the 60 s error, and K = 1 cost nothing at 8 s: docs/results.md, "Four references").
    int interleave = 0;
    // 0 (the default): render::default_batches_per_position of the scene's triangles
    // (batches_per_position_for).
    int batches_per_position = 0;
    // 0 (the default): devices_for's choice.
    int devices = 0;
    static constexpr int kDefaultInterleave = 2;
    static constexpr uint64_t kInterleaveMinPixels = 256 * 256;
    // The interleave for a render of `scene` with these chains: --interleave K as given, or the
    // default above.
    uint32_t interleave_for(const scene::Scene& scene, const light::ChainOptions& chains,
                            uint32_t width, uint32_t height) const;
    // --batches-per-position N as given, or the scene's default.
    uint32_t batches_per_position_for(const scene::Scene& scene) const;
    // --devices N as given, or render::default_render_devices.
    uint32_t devices_for(const gpu::DeviceInfo& device) const;
    // The radius of the virtual spherical lights (scene diagonals), 0 with --no-vsl.
    float vsl() const { return no_vsl ? 0.0f : vsl_radius; }

    // Copies them into `o` (the chains' max depth is the command's to set).
    void apply(render::RenderOptions& o) const;
};
// window: the preview's (its --devices default differs: preview_app.h).
void add_renderer_options(ArgParser& parser, RendererArgs& args, bool window = false);

// --compensate (the default), --no-compensate, --compensation-spp: clamping compensation
// (engine/integrator/clamp_compensation.h) on a CPU thread beside the GPU.
struct CompensationArgs {
    bool compensate = false;
    bool no_compensate = false;
    int spp = 0;  // 0: one pass per 32 VPLs shaded

    // On unless --no-compensate.
    bool enabled() const { return !no_compensate; }
};
void add_compensation_options(ArgParser& parser, CompensationArgs& args);

// --no-caustics: no caustic tracer (engine/integrator/caustic_tracer.h) beside the GPU; the light
// tracer then leaves VPLs on near-specular surfaces again.
void add_caustics_option(ArgParser& parser, bool& no_caustics);

// --pool, --rows, --clusters, --matrix, --row-resolution: matrix row-column sampling
// (engine/manylights), off unless --pool N is given; the defaults are RowColumnOptions'.
struct ManyLightsArgs {
    std::string pool = "auto";  // or VPLs per pool, 0: every VPL shaded
    int rows = int(manylights::RowColumnOptions{}.rows);
    int clusters = int(manylights::RowColumnOptions{}.clusters);
    std::string matrix = "auto";
    int row_resolution = int(manylights::RowColumnOptions{}.row_resolution);

    // With `--pool auto` every VPL shaded: bench, convergence and the preview take pools by hand.
    manylights::RowColumnOptions options() const;
    // render's: `auto` resolved by manylights::automatic_pool for the scene, the sampler, the
    // time budget (0: a fixed VPL count) and whether the renderer is a CPU implementation of
    // Vulkan (on every rank: cpu_devices).
    manylights::RowColumnOptions options_for(const scene::Scene& scene, const std::string& sampler,
                                             double time_budget, bool cpu_device) const;
};
void add_many_lights_options(ArgParser& parser, ManyLightsArgs& args);

// --sampler: a name of sampler::sampler_names().
void add_sampler_option(ArgParser& parser, std::string& name);

// --beta, --sigma, --chains, --importance-points, --bootstrap, --direct-stride: the Metropolis
// sampler's.
void add_metropolis_options(ArgParser& parser, sampler::SamplerSettings& settings);

// --max-depth (Mitsuba's max_depth; the default is the target's) and --seed.
void add_max_depth_option(ArgParser& parser, int& max_depth);
// --device: a Vulkan device index of mvpl info, or -1 for the default; `value_name` for commands
// that also take a word (render and convergence under mpirun: local-rank).
void add_device_option(ArgParser& parser, int& device, const std::string& help,
                       const std::string& value_name = "N");
void add_seed_option(ArgParser& parser, uint64_t& seed);
// --vpl-per-path all|one (empty: each sampler's default), and its effect on `settings`.
void add_vpl_per_path_option(ArgParser& parser, std::string& per_path);
void apply_vpl_per_path(const std::string& per_path, sampler::SamplerSettings& settings);
// --write-every SEC (render, reference): rewrite the outputs between chunks (checkpoints.h); its
// check's message names `command`.
void add_write_every_option(ArgParser& parser, float& seconds, const std::string& command);

// --camera N, --look-at EX,EY,EZ,TX,TY,TZ[,UX,UY,UZ], --fov DEG: which camera to render from.
struct CameraArgs {
    int camera = -1;
    std::string look_at;
    float fov = 0.0f;
    scene::CameraChoice choice;  // filled by the parser's check
};
void add_camera_options(ArgParser& parser, CameraArgs& args);

// --env FILE, --env-color R,G,B, --env-scale S, --env-rotate DEG, --no-default-light: the
// environment around the scene (scene::EnvironmentChoice).
struct EnvironmentArgs {
    std::string map;
    float rotate = 0.0f;
    std::string color;
    float scale = 1.0f;
    bool no_default_light = false;
    session::EnvironmentChoice choice;  // filled by the parser's check
};
void add_environment_options(ArgParser& parser, EnvironmentArgs& args);

// -D NAME=VALUE and -a PATH (both repeatable): a Mitsuba XML scene's parameters and the folders
// its relative file names are searched in, as Mitsuba's command line takes them.
struct SceneFileArgs {
    std::vector<std::string> defines;
    std::vector<std::string> paths;
    scene::LoadOptions options;  // filled by the parser's check
};
void add_scene_file_options(ArgParser& parser, SceneFileArgs& args);

// What the scene file asks for where the command line did not: its integrator's max_depth for
// --max-depth and its film size for --res (either pointer may be null).
void apply_scene_defaults(const ArgParser& parser, const scene::Scene& scene, int* max_depth,
                          int* width, int* height);

// What a Mitsuba 0.6 `vpl` integrator asks for where the command line did not: its
// shadowMapResolution for --shadow-res and its clamping, mapped onto --clamp for light paths of
// `max_depth` (sampler/mitsuba_clamping.h: Mitsuba clamps per VPL, mvpl at one distance).
void apply_vpl_integrator_defaults(const ArgParser& parser, const session::SceneSession& session,
                                   int max_depth, RendererArgs& renderer);

}  // namespace mvpl::cli
