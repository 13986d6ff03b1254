#pragma once
// Named VPL samplers for the command line: make_vpl_stream("mc" | "metropolis", …).
#include <memory>
#include <string>
#include <vector>

#include "engine/core/image_size.h"
#include "engine/light/chain_options.h"
#include "engine/light/light_sampler.h"
#include "engine/sampler/metropolis_stream.h"
#include "engine/sampler/monte_carlo_sampler.h"
#include "engine/sampler/vpl_stream.h"
#include "engine/scene/scene.h"
#include "engine/trace/accel.h"

namespace mvpl::sampler {

// Everything either sampler may need; each reads its own part.
struct SamplerSettings {
    uint64_t seed = 0;
    LightTracerOptions tracer;
    // Monte Carlo. Halton paths by default: their relMSE's median over seeds was 0.66–0.80× that
    // of random paths at equal time on the Cornell box, the glossy scene, Duck and
    // EnvironmentTest (four seeds, 10 s), and 0.72× on the two rooms at 4096 VPLs (twelve seeds,
    // mean 0.47×, the worst seed 0.019 against 0.078): docs/results.md, "Halton light paths".
    bool qmc = true;
    VplsPerPath per_path = VplsPerPath::All;
    // Metropolis (the image size and clamp also shape the importance points)
    int width = int(kDefaultImageWidth);
    int height = int(kDefaultImageHeight);
    float clamp = ImportanceOptions{}.clamp;
    float vsl_radius = ImportanceOptions{}.vsl_radius;
    // Defaults are MetropolisOptions' own (measured there), not copies.
    float large_step = MetropolisOptions{}.large_step;
    float sigma = MetropolisOptions{}.sigma;
    int chains = MetropolisOptions{}.chains;
    int importance_points = ImportanceOptions{}.points;
    float absolute_share = float(MetropolisOptions{}.importance.absolute_share);
    uint64_t bootstrap = MetropolisOptions{}.bootstrap;
    double defensive = MetropolisOptions{}.defensive;
    VplsPerPath metropolis_per_path = MetropolisOptions{}.per_path;
    int direct_stride = MetropolisOptions{}.direct_stride;
    // The renderer's specular chains, which the Metropolis target follows as the image does.
    light::ChainOptions specular_chains;
    // The ranks that share the stream (null: this process alone).
    cluster::Cluster* cluster = nullptr;
};

const std::vector<std::string>& sampler_names();

// Throws UsageError naming the available samplers when `name` is none of them. scene, accel and
// lights must outlive the stream. The Metropolis stream runs its bootstrap here.
std::unique_ptr<VplStream> make_vpl_stream(const std::string& name, const scene::Scene& scene,
                                           const trace::Accel& accel,
                                           const light::LightSampler& lights,
                                           const scene::Camera& camera,
                                           const SamplerSettings& settings);

// The Metropolis options the settings describe (tests and tools that need the concrete stream).
MetropolisOptions metropolis_options(const SamplerSettings& settings);

}  // namespace mvpl::sampler
