#include "engine/sampler/sampler_factory.h"

#include "engine/core/error.h"
#include "engine/sampler/monte_carlo_stream.h"

namespace mvpl::sampler {

const std::vector<std::string>& sampler_names() {
    static const std::vector<std::string> names{"mc", "metropolis"};
    return names;
}

MetropolisOptions metropolis_options(const SamplerSettings& s) {
    MetropolisOptions o;
    o.seed = s.seed;
    o.chains = s.chains;
    o.large_step = s.large_step;
    o.sigma = s.sigma;
    o.bootstrap = s.bootstrap;
    o.defensive = s.defensive;
    o.tracer = s.tracer;
    o.per_path = s.metropolis_per_path;
    o.direct_stride = s.direct_stride;
    o.importance.points = s.importance_points;
    o.importance.absolute_share = s.absolute_share;
    o.importance.width = s.width;
    o.importance.height = s.height;
    o.importance.clamp = s.clamp;
    o.importance.vsl_radius = s.vsl_radius;
    o.importance.seed = s.seed;
    o.importance.chains = s.specular_chains;
    o.cluster = s.cluster;
    return o;
}

std::unique_ptr<VplStream> make_vpl_stream(const std::string& name, const scene::Scene& scene,
                                           const trace::Accel& accel,
                                           const light::LightSampler& lights,
                                           const scene::Camera& camera,
                                           const SamplerSettings& settings) {
    if (name == "mc") {
        MonteCarloOptions o;
        o.seed = settings.seed;
        o.qmc = settings.qmc;
        o.per_path = settings.per_path;
        o.tracer = settings.tracer;
        o.cluster = settings.cluster;
        return std::make_unique<MonteCarloStream>(scene, accel, lights, o);
    }
    if (name == "metropolis") {
        return std::make_unique<MetropolisStream>(scene, accel, lights, camera,
                                                  metropolis_options(settings));
    }
    std::string available;
    for (const std::string& n : sampler_names())
        available += (available.empty() ? "" : ", ") + n;
    throw UsageError("unknown sampler '" + name + "' (available: " + available + ")");
}

}  // namespace mvpl::sampler
