#pragma once
// `mvpl render`'s options, declared once for the command line (render_command.cpp) and the Python
// module (python/), whose keywords are these options' names: what it reads, and the estimate
// (engine/integrator/estimate.h) they ask for.
#include <cstdint>
#include <string>
#include <vector>

#include "engine/core/image_size.h"
#include "engine/integrator/estimate.h"
#include "engine/sampler/monte_carlo_sampler.h"
#include "engine/scene/scene.h"
#include "tools/cli/arg_parser.h"
#include "tools/cli/option_groups.h"

namespace mvpl::cli {

// Everything `mvpl render` reads from its command line.
struct RenderArgs {
    std::string scene_path;
    CameraArgs camera;
    EnvironmentArgs environment;
    SceneFileArgs scene_file;
    std::string sampler_name = "mc";
    std::string per_path;  // empty: each sampler's default
    uint64_t paths = sampler::kDefaultPaths;
    int width = int(kDefaultImageWidth), height = int(kDefaultImageHeight);
    RendererArgs renderer;
    std::vector<std::string> outputs;
    std::string aovs;  // --aov (exr_outputs.h)
    float exposure = 0.0f;
    int device = -1;
    bool qmc = false, random_paths = false, oracle = false, quiet = false;
    CompensationArgs compensation;
    ManyLightsArgs many_lights;
    bool no_caustics = false;
    std::string dump_shaders;
    bool no_shader_cache = false;
    float time_budget = 0.0f;
    float write_every = 0.0f;  // --write-every SEC (0: only at the end)
    sampler::SamplerSettings settings;
};

// SCENE and the options, with their checks.
void add_render_options(ArgParser& parser, RenderArgs& a);

// The estimate the parsed options ask for on `scene` (after apply_scene_defaults); throws
// UsageError for options that exclude each other. Scales the Metropolis sampler's pool to
// --time-budget unless --chains or --bootstrap were given. `cpu_device`: whether the renderer is
// a CPU implementation of Vulkan (on every rank), which `--pool auto` reads.
integrator::Estimate render_estimate(const ArgParser& parser, RenderArgs& a,
                                     const scene::Scene& scene, bool cpu_device);

}  // namespace mvpl::cli
