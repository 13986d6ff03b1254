#include "tools/cli/option_groups.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <vector>

#include "engine/core/error.h"
#include "engine/light/specular_chain.h"
#include "engine/render/batch_plan.h"
#include "engine/render/device_split.h"
#include "engine/sampler/mitsuba_clamping.h"

namespace mvpl::cli {

namespace {

// "COMMAND: OPTION must be in RANGE": the one format of every range error.
[[noreturn]] void out_of_range(const ArgParser& parser, const std::string& option,
                               const std::string& range) {
    throw UsageError(parser.command() + ": " + option + " must be in " + range);
}

// The comma-separated numbers of an option's value, each finite.
std::vector<float> finite_numbers(const ArgParser& parser, const std::string& option,
                                  const std::string& text) {
    std::vector<float> v;
    size_t start = 0;
    while (start <= text.size()) {
        const size_t comma = std::min(text.find(',', start), text.size());
        const std::string item = text.substr(start, comma - start);
        char* end = nullptr;
        const float x = std::strtof(item.c_str(), &end);
        if (item.empty() || *end != '\0' || !std::isfinite(x))
            throw UsageError(parser.command() + ": " + option + ": '" + item +
                             "' is not a finite number");
        v.push_back(x);
        start = comma + 1;
    }
    return v;
}

}  // namespace

uint32_t RendererArgs::interleave_for(const scene::Scene& scene, const light::ChainOptions& chains,
                                      uint32_t width, uint32_t height) const {
    if (interleave > 0) return uint32_t(interleave);
    if (uint64_t(width) * height < kInterleaveMinPixels) return 1u;
    return light::scene_may_chain(scene, chains) ? 1u : uint32_t(kDefaultInterleave);
}

uint32_t RendererArgs::batches_per_position_for(const scene::Scene& scene) const {
    if (batches_per_position > 0) return uint32_t(batches_per_position);
    return render::default_batches_per_position(scene.triangle_count());
}

uint32_t RendererArgs::devices_for(const gpu::DeviceInfo& device) const {
    return devices > 0 ? uint32_t(devices) : render::default_render_devices(device);
}

void RendererArgs::apply(render::RenderOptions& o) const {
    o.shadow_resolution = uint32_t(shadow_res);
    o.batch = uint32_t(batch);
    o.clamp = clamp;
    o.vsl_radius = vsl();
    o.shadow_culling = !no_shadow_culling;
    o.shadow_proxy = !no_shadow_proxy;
    o.shadow_lod = !no_shadow_lod;
    o.backface_culling = !no_backface_culling;
    o.jitter = !no_jitter;
    o.chains.max_roughness = no_chains ? -1.0f : chain_roughness;
    o.chains.emission_samples = chain_samples;
    o.hemicube = !no_hemicube;
    o.vpl_culling = !no_vpl_culling;
    o.interleave = uint32_t(interleave > 0 ? interleave : kDefaultInterleave);
    // The scene's default needs the scene: batches_per_position_for.
    o.batches_per_position = uint32_t(std::max(batches_per_position, 1));
}

namespace {

const char* devices_help(bool window) {
    if (window) {
        return "logical Vulkan devices, dealt the sub-pixel positions in turn and run at once, "
               "their images summed for the window (0 = 1: a frame's few batches keep one busy "
               "at a time)";
    }
    return "logical Vulkan devices that shade a run of every chunk's batches each, all at once "
           "(0 = 2 on a CPU device such as lavapipe, where one's shadow geometry runs beside the "
           "other's rasterisation; 1 on a GPU)";
}

}  // namespace

void add_renderer_options(ArgParser& parser, RendererArgs& args, bool window) {
    parser.begin_group("GPU renderer");
    parser.add_int("--shadow-res", &args.shadow_res, "side of a shadow cube face in texels");
    parser.add_int("--batch", &args.batch, "VPLs per shadow/shading batch");
    parser.add_float("--clamp", &args.clamp,
                     "clamping distance as a fraction of the scene diagonal (0 = off)");
    parser.add_float("--vsl-radius", &args.vsl_radius,
                     "radius of the virtual spherical lights that surface and area VPLs become, "
                     "as a fraction of the scene diagonal: glossy lobes are integrated over it");
    parser.add_flag("--no-vsl", &args.no_vsl,
                    "shade surface and area VPLs as points (glossy lobes evaluated along one ray)");
    parser.add_flag("--no-shadow-culling", &args.no_shadow_culling,
                    "draw every triangle into every shadow face (default: only the clusters a "
                    "face can see)");
    parser.add_flag("--no-shadow-proxy", &args.no_shadow_proxy,
                    "surface VPLs draw the full geometry into their shadow maps (default: "
                    "the levels of detail of meshes of 4096+ triangles, as --no-shadow-lod says)");
    parser.add_flag("--no-shadow-lod", &args.no_shadow_lod,
                    "shadow maps draw meshes of 4096+ triangles in full "
                    "(default: each at the coarsest level of detail whose error stays below a "
                    "shadow texel at its distance)");
    parser.add_flag("--no-backface-culling", &args.no_backface_culling,
                    "shadow maps draw both faces of every triangle (default: closed meshes of "
                    "4096+ triangles only their faces towards a VPL outside them; the same image)");
    parser.add_flag("--no-hemicube", &args.no_hemicube,
                    "surface and area VPLs draw whole shadow cube faces (default: only the part "
                    "their lit hemisphere reaches)");
    parser.add_flag("--no-vpl-culling", &args.no_vpl_culling,
                    "keep surface and area VPLs whose lit side holds nothing in view (default: "
                    "they are neither drawn nor shaded)");
    parser.add_int("--interleave", &args.interleave,
                   "interleaved sampling: each pixel of a K×K block shades 1/K² of every batch, "
                   "then a geometry-aware K×K filter (1 = off; 0 = 2, or 1 below 256² pixels or "
                   "where specular "
                   "chains are traced)",
                   "K");
    parser.add_int("--batches-per-position", &args.batches_per_position,
                   "batches shaded at each sub-pixel position, each position's G-buffer drawn "
                   "once (0 = one per 65536 scene triangles, from 2 to 8: heavy scenes draw "
                   "fewer G-buffers)");
    parser.add_int("--devices", &args.devices, devices_help(window));
    parser.add_flag("--no-jitter", &args.no_jitter,
                    "shade every batch at the pixel centres (no anti-aliasing; for debugging)");
    // "Specular" tells these from the Metropolis sampler's --chains; the short names stay.
    parser.begin_group("Specular chains");
    parser.add_float("--specular-chain-roughness", &args.chain_roughness,
                     "continue camera paths through surfaces this glossy or glossier (perceptual "
                     "roughness) to the first rougher one, which the VPLs light");
    parser.add_alias("--chain-roughness", "--specular-chain-roughness");
    parser.add_flag("--no-specular-chains", &args.no_chains,
                    "light glossy surfaces with the VPLs directly (no specular chains)");
    parser.add_alias("--no-chains", "--no-specular-chains");
    parser.add_int("--specular-chain-samples", &args.chain_samples,
                   "sub-pixel samples per batch of the light that glossy pixels reflect directly "
                   "(their highlights), where the pixel's centre is glossy");
    parser.add_alias("--chain-samples", "--specular-chain-samples");
    // The renderer's limits: 4096² faces × 6 × a batch must still fit in memory.
    parser.add_check([&parser, &args] {
        if (args.shadow_res < 4 || args.shadow_res > 4096)
            out_of_range(parser, "--shadow-res", "4..4096");
        if (args.batch < 1 || args.batch > 256) out_of_range(parser, "--batch", "1..256");
        if (!(args.clamp >= 0.0f && args.clamp <= 1.0f)) out_of_range(parser, "--clamp", "[0, 1]");
        if (!(args.vsl_radius >= 0.0f && args.vsl_radius <= 1.0f))
            out_of_range(parser, "--vsl-radius", "[0, 1]");
        if (!(args.chain_roughness >= 0.0f && args.chain_roughness <= 1.0f))
            out_of_range(parser, "--specular-chain-roughness", "[0, 1]");
        if (args.interleave < 0 || args.interleave > 8)
            out_of_range(parser, "--interleave", "0..8");
        if (args.batches_per_position < 0 || args.batches_per_position > 1024)
            out_of_range(parser, "--batches-per-position", "0..1024");
        if (args.devices < 0 || args.devices > int(render::kMaxRenderDevices))
            out_of_range(parser, "--devices", "0.." + std::to_string(render::kMaxRenderDevices));
        if (args.chain_samples < 1 || args.chain_samples > 64)
            out_of_range(parser, "--specular-chain-samples", "1..64");
    });
}

void add_compensation_options(ArgParser& parser, CompensationArgs& args) {
    parser.begin_group("Clamping compensation");
    parser.add_flag("--compensate", &args.compensate,
                    "recover the light that --clamp removes (the default): BSDF-sampled CPU "
                    "rays from each pixel, bounded by the clamping distance (Kollig & Keller "
                    "2004), while the GPU renders");
    parser.add_flag("--no-compensate", &args.no_compensate,
                    "leave the clamped light out (biased dark in corners, no CPU rays)");
    parser.add_int("--compensation-spp", &args.spp,
                   "compensation samples per pixel; 0: one per 32 VPLs shaded (at most 64 in a "
                   "render of fixed size)");
    parser.add_check([&parser, &args] {
        if (args.compensate && args.no_compensate)
            throw UsageError(parser.command() +
                             ": --compensate and --no-compensate exclude "
                             "each other");
        if (args.spp < 0 || args.spp > 65536)
            out_of_range(parser, "--compensation-spp", "0..65536");
    });
}

void add_caustics_option(ArgParser& parser, bool& no_caustics) {
    parser.begin_group("Caustics");
    parser.add_flag("--no-caustics", &no_caustics,
                    "no light tracing of caustics (light through glass or off near-mirrors onto "
                    "rough surfaces) on a CPU thread beside the GPU; near-mirrors get VPLs instead "
                    "and light through glass is lost");
}

namespace {

constexpr long long kMaxPool = 1 << 20;

// --pool's value as VPLs per pool; none for `auto` or a value add_many_lights_options refuses.
std::optional<uint32_t> explicit_pool(const std::string& value) {
    if (value.empty() || value == "auto") return std::nullopt;
    char* end = nullptr;
    errno = 0;
    const long long n = std::strtoll(value.c_str(), &end, 10);
    if (*end != '\0' || errno != 0 || n < 0 || n > kMaxPool) return std::nullopt;
    return uint32_t(n);
}

}  // namespace

manylights::RowColumnOptions ManyLightsArgs::options_for(const scene::Scene& scene,
                                                         const std::string& sampler,
                                                         double time_budget,
                                                         bool cpu_device) const {
    manylights::RowColumnOptions o = options();
    if (pool == "auto")
        o.pool = manylights::automatic_pool(scene, sampler, time_budget, cpu_device);
    return o;
}

manylights::RowColumnOptions ManyLightsArgs::options() const {
    manylights::RowColumnOptions o;
    o.pool = explicit_pool(pool).value_or(0);
    o.rows = uint32_t(rows);
    o.clusters = uint32_t(clusters);
    o.matrix = matrix == "gpu"   ? manylights::MatrixDevice::gpu
               : matrix == "cpu" ? manylights::MatrixDevice::cpu
                                 : manylights::MatrixDevice::automatic;
    o.row_resolution = uint32_t(row_resolution);
    return o;
}

void add_many_lights_options(ArgParser& parser, ManyLightsArgs& o) {
    parser.begin_group("Many lights");
    parser.add_string(
        "--pool", &o.pool,
        "matrix row-column sampling (Hašan et al. 2007): shade each pool of N VPLs through "
        "--clusters weighted representatives chosen from their light on --rows camera-visible "
        "points; 0: every VPL shaded; auto (render's default): " +
            std::to_string(manylights::kAutomaticPool) +
            " for renders of a --time-budget of at least " +
            std::to_string(int(manylights::kAutomaticMinSeconds)) + " s (mc) or " +
            std::to_string(int(manylights::kAutomaticMinSecondsMetropolis)) +
            " s (metropolis) of scenes whose materials are all diffuse, under no sky, on lavapipe "
            "(where it paid), else 0; bench, convergence and preview: 0",
        "auto|N");
    parser.add_int("--rows", &o.rows, "camera-visible points of the reduced matrix");
    parser.add_int("--clusters", &o.clusters,
                   "representatives shaded per pool; 0: a " +
                       std::to_string(manylights::kVplsPerCluster) + "th of --pool");
    parser.add_string("--matrix", &o.matrix,
                      "where the reduced matrix is evaluated: gpu (a distance cube per row, the "
                      "shading pass's code), cpu (Embree rays, the oracle's) or auto (default: "
                      "gpu, except on lavapipe for pools below " +
                          std::to_string(manylights::kGpuMatrixPoolOnCpuDevice) + ")",
                      "auto|gpu|cpu");
    parser.add_int("--row-resolution", &o.row_resolution,
                   "side of a row's distance cube face in texels (--matrix gpu)");
    parser.add_check([&parser, &o] {
        if (o.matrix != "auto" && o.matrix != "gpu" && o.matrix != "cpu")
            throw UsageError(parser.command() + ": --matrix is auto, gpu or cpu, not '" + o.matrix +
                             "'");
        if (o.row_resolution < 4 || o.row_resolution > 4096)
            out_of_range(parser, "--row-resolution", "4..4096");
        if (o.pool != "auto" && !explicit_pool(o.pool))
            throw UsageError(parser.command() + ": --pool is auto or a number in 0..2^20, not '" +
                             o.pool + "'");
        if (o.rows < 1 || o.rows > 65536) out_of_range(parser, "--rows", "1..65536");
        if (o.clusters < 0 || o.clusters > (1 << 20)) out_of_range(parser, "--clusters", "0..2^20");
    });
}

void add_sampler_option(ArgParser& parser, std::string& name) {
    parser.begin_group("Sampler");
    std::string choices;
    for (const std::string& n : sampler::sampler_names())
        choices += (choices.empty() ? "" : "|") + n;
    parser.add_string("--sampler", &name, "VPL sampler: mc (default) or metropolis", choices);
    parser.add_check([&parser, &name] {
        const std::vector<std::string>& names = sampler::sampler_names();
        if (std::find(names.begin(), names.end(), name) != names.end()) return;
        std::string available;
        for (const std::string& n : names)
            available += (available.empty() ? "" : ", ") + n;
        throw UsageError(parser.command() + ": unknown --sampler '" + name +
                         "' (available: " + available + ")");
    });
}

void add_metropolis_options(ArgParser& parser, sampler::SamplerSettings& s) {
    parser.begin_group("Metropolis sampler");
    parser.add_float("--beta", &s.large_step, "large-step probability");
    parser.add_float("--sigma", &s.sigma, "small-step width in primary sample space");
    parser.add_int("--chains", &s.chains,
                   "independent Metropolis chains (Markov chains of VPLs, not the specular "
                   "chains of camera paths)");
    parser.add_int("--importance-points", &s.importance_points,
                   "camera-visible points of the target");
    parser.add_uint64("--bootstrap", &s.bootstrap, "independent paths for the normalisation");
    parser.add_float("--absolute-share", &s.absolute_share,
                     "share of the target's mass on plain luminance (the image's mean) beside the "
                     "relative weights");
    parser.add_int("--direct-stride", &s.direct_stride,
                   "Metropolis chain steps per emitter VPL of the direct light's own stratified "
                   "sequence; 0 = the chains carry the direct light too");
    parser.add_check([&parser, &s] {
        if (!(s.large_step >= 0.0f && s.large_step <= 1.0f))
            out_of_range(parser, "--beta", "[0, 1]");
        if (!(s.sigma > 0.0f && s.sigma <= 1.0f)) out_of_range(parser, "--sigma", "(0, 1]");
        if (s.chains < 1 || s.chains > (1 << 16)) out_of_range(parser, "--chains", "1..65536");
        if (s.importance_points < 1 || s.importance_points > (1 << 20))
            out_of_range(parser, "--importance-points", "1..2^20");
        if (s.bootstrap < 1 || s.bootstrap > (uint64_t(1) << 26))
            out_of_range(parser, "--bootstrap", "1..2^26");
        if (!(s.absolute_share >= 0.0f && s.absolute_share <= 1.0f))
            out_of_range(parser, "--absolute-share", "[0, 1]");
        if (s.direct_stride < 0 || s.direct_stride > (1 << 20))
            out_of_range(parser, "--direct-stride", "0..2^20");
    });
}

void add_max_depth_option(ArgParser& parser, int& max_depth) {
    parser.begin_group("Path depth");
    parser.add_int("--max-depth", &max_depth,
                   "path segments from the camera to the light (Mitsuba's max_depth; 1 = emitters, "
                   "2 = direct light, -1 = unlimited)");
    // 0 would show nothing and other negatives are not a depth: neither is taken silently as
    // something else.
    parser.add_check([&parser, &max_depth] {
        if (max_depth != -1 && (max_depth < 1 || max_depth > 1024))
            out_of_range(parser, "--max-depth", "1..1024, or -1 for unlimited");
    });
}

void add_device_option(ArgParser& parser, int& device, const std::string& help,
                       const std::string& value_name) {
    parser.begin_group("Device");
    parser.add_int("--device", &device, help, value_name);
    parser.add_check([&parser, &device] {
        if (device < -1 || device > 1023)
            out_of_range(parser, "--device", "0..1023 (see mvpl info), or -1 for the default");
    });
}

void add_seed_option(ArgParser& parser, uint64_t& seed) {
    parser.begin_group("Seed");
    parser.add_uint64("--seed", &seed, "random seed; the same seed gives the same result");
}

void add_vpl_per_path_option(ArgParser& parser, std::string& per_path) {
    parser.add_string("--vpl-per-path", &per_path,
                      "VPLs a light path leaves: all (one per bounce) or one (the seed paper's "
                      "choice); default all for mc, one for metropolis",
                      "all|one");
    parser.add_check([&parser, &per_path] {
        if (!per_path.empty() && per_path != "all" && per_path != "one")
            throw UsageError(parser.command() + ": --vpl-per-path must be all or one");
    });
}

void apply_vpl_per_path(const std::string& per_path, sampler::SamplerSettings& settings) {
    if (per_path == "one") settings.per_path = sampler::VplsPerPath::One;
    if (per_path == "all") settings.metropolis_per_path = sampler::VplsPerPath::All;
}

void add_write_every_option(ArgParser& parser, float& seconds, const std::string& command) {
    parser.add_float("--write-every", &seconds,
                     "rewrite every -o with the image so far every SEC seconds, between chunks "
                     "(0: only at the end)",
                     "SEC");
    parser.add_check([&seconds, command] {
        if (!(seconds >= 0.0f && seconds <= 1e6f))
            throw UsageError(command + ": --write-every must be in [0, 1e6] seconds");
    });
}

void add_camera_options(ArgParser& parser, CameraArgs& args) {
    parser.begin_group("Camera");
    parser.add_int("--camera", &args.camera,
                   "render from the file's perspective camera N (0 = the first; default: the "
                   "first, or a three-quarter view of the bounds without one)");
    parser.add_string("--look-at", &args.look_at, "a camera at E looking at T, up U (+Y)",
                      "EX,EY,EZ,TX,TY,TZ[,UX,UY,UZ]");
    parser.add_float("--fov", &args.fov, "vertical field of view in degrees (0 = the camera's)",
                     "DEG");
    parser.add_check([&parser, &args] {
        if (args.camera < -1 || args.camera > 1000000)
            out_of_range(parser, "--camera", "0..1000000");
        if (!(args.fov >= 0.0f && args.fov < 180.0f)) out_of_range(parser, "--fov", "(0, 180)");
        scene::CameraChoice& c = args.choice;
        c.index = args.camera;
        c.fov_degrees = args.fov;
        if (args.look_at.empty()) return;
        const std::vector<float> v = finite_numbers(parser, "--look-at", args.look_at);
        if (v.size() != 6 && v.size() != 9) {
            throw UsageError(parser.command() + ": --look-at takes 6 or 9 numbers, not " +
                             std::to_string(v.size()));
        }
        c.look_at = true;
        c.eye = Vec3(v[0], v[1], v[2]);
        c.target = Vec3(v[3], v[4], v[5]);
        if (v.size() == 9) c.up = Vec3(v[6], v[7], v[8]);
        if (!(glm::length(c.eye - c.target) > 0.0f))
            throw UsageError(parser.command() + ": --look-at: the eye is the target");
    });
}

void add_environment_options(ArgParser& parser, EnvironmentArgs& args) {
    parser.begin_group("Environment");
    parser.add_string("--env", &args.map,
                      "latitude-longitude environment map around the scene (.hdr or .exr, twice "
                      "as wide as high; its centre faces +X, its top +Y)",
                      "FILE");
    parser.add_float("--env-rotate", &args.rotate, "turns the environment map about +Y (degrees)",
                     "DEG");
    parser.add_string("--env-color", &args.color,
                      "a uniform environment of this radiance around the scene (linear); with "
                      "--env, the map's tint",
                      "R,G,B");
    parser.add_float("--env-scale", &args.scale, "multiplies the environment's radiance");
    parser.add_flag("--no-default-light", &args.no_default_light,
                    "a scene without light, or whose emission is too weak to light it, stays "
                    "dark (default: a uniform white sky)");
    parser.add_check([&parser, &args] {
        // The range scene_range.h gives emitted radiance.
        if (!(args.scale >= 0.0f && args.scale <= 1e15f))
            out_of_range(parser, "--env-scale", "[0, 1e15]");
        if (!std::isfinite(args.rotate)) out_of_range(parser, "--env-rotate", "finite degrees");
        session::EnvironmentChoice& c = args.choice;
        c.scale = args.scale;
        c.default_light = !args.no_default_light;
        c.map = args.map;
        c.rotation_degrees = args.rotate;
        if (args.color.empty()) return;
        const std::vector<float> v = finite_numbers(parser, "--env-color", args.color);
        if (v.size() != 3)
            throw UsageError(parser.command() + ": --env-color takes 3 numbers, not " +
                             std::to_string(v.size()));
        for (float x : v) {
            if (!(x >= 0.0f && x <= 1e15f)) out_of_range(parser, "--env-color", "[0, 1e15]");
        }
        c.has_color = true;
        c.color = Rgb(v[0], v[1], v[2]);
    });
}

void add_scene_file_options(ArgParser& parser, SceneFileArgs& args) {
    parser.begin_group("Mitsuba scene file");
    parser.add_strings("-D", &args.defines,
                       "a Mitsuba XML parameter ($NAME), overriding its <default>", "NAME=VALUE");
    parser.add_strings("-a", &args.paths,
                       "a folder where a Mitsuba XML scene's relative file names are searched",
                       "DIR");
    parser.add_check([&parser, &args] {
        args.options = {};
        for (const std::string& d : args.defines) {
            const size_t eq = d.find('=');
            if (eq == std::string::npos || eq == 0)
                throw UsageError(parser.command() + ": -D '" + d + "' is not NAME=VALUE");
            args.options.defines.emplace_back(d.substr(0, eq), d.substr(eq + 1));
        }
        args.options.search_paths = args.paths;
    });
}

void apply_scene_defaults(const ArgParser& parser, const scene::Scene& scene, int* max_depth,
                          int* width, int* height) {
    if (max_depth && scene.max_depth != 0 && !parser.given("--max-depth"))
        *max_depth = scene.max_depth;
    if (width && height && scene.film_width > 0 && scene.film_height > 0 &&
        !parser.given("--res")) {
        *width = scene.film_width;
        *height = scene.film_height;
    }
}

void apply_vpl_integrator_defaults(const ArgParser& parser, const session::SceneSession& session,
                                   int max_depth, RendererArgs& renderer) {
    const scene::Scene& scene = session.scene();
    if (scene.shadow_resolution > 0 && !parser.given("--shadow-res"))
        renderer.shadow_res = scene.shadow_resolution;
    if (scene.vpl_clamping >= 0.0f && !parser.given("--clamp")) {
        renderer.clamp = sampler::mitsuba_clamp(scene, session.accel(), session.lights(),
                                                scene.vpl_clamping, max_depth);
    }
}

}  // namespace mvpl::cli
