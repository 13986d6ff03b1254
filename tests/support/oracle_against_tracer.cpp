#include "tests/support/oracle_against_tracer.h"

#include <cmath>
#include <vector>

#include "engine/core/subpixel.h"
#include "engine/light/light_sampler.h"
#include "engine/reference/path_tracer.h"
#include "engine/reference/vpl_gather.h"
#include "engine/sampler/monte_carlo_sampler.h"
#include "engine/trace/accel.h"

namespace mvpl::test {

double OracleTracerMeans::sigma() const {
    return std::sqrt(oracle.standard_error * oracle.standard_error +
                     tracer.standard_error * tracer.standard_error);
}

OracleTracerMeans compare_oracle_with_tracer(const scene::Scene& scene,
                                             const OracleAgainstTracer& setup,
                                             const std::function<double(const Image&)>& reduce) {
    const trace::Accel accel(scene);
    const light::LightSampler lights(scene);
    std::vector<double> oracle, tracer;
    OracleTracerMeans out;
    for (int run = 0; run < setup.runs; ++run) {
        const uint64_t seed = uint64_t(run + 1);
        sampler::MonteCarloOptions mc;
        mc.paths = setup.paths;
        mc.seed = seed;
        mc.tracer.max_depth = setup.max_depth;
        const light::VplSet vpls = sampler::MonteCarloSampler(scene, accel, lights).generate(mc);
        reference::GatherOptions g;
        g.width = g.height = setup.size;
        g.clamp = 0.0f;       // unbiased, as the path tracer
        g.vsl_radius = 0.0f;  // point VPLs: unbiased too (virtual spheres blur glossy lobes)
        g.max_depth = setup.max_depth;
        g.chains.max_roughness = setup.chain_roughness;
        g.chains.max_depth = setup.max_depth;
        g.chain_seed = seed;
        if (setup.rotate_subpixel) g.subpixel.rotation = subpixel_rotation(seed);
        oracle.push_back(reduce(reference::gather_vpls(scene, accel, vpls, g)));
        if (run == 0) {
            reference::GatherOptions off = g;
            off.chains.max_roughness = -1.0f;
            out.without_chains = reduce(reference::gather_vpls(scene, accel, vpls, off));
        }
        reference::PathTracerOptions o;
        o.width = o.height = setup.size;
        o.spp = setup.spp;
        o.max_depth = setup.max_depth;
        o.seed = seed;
        o.quiet = true;
        tracer.push_back(reduce(reference::PathTracer(scene, accel, lights).render(o)));
    }
    out.oracle = mean_and_error(oracle);
    out.tracer = mean_and_error(tracer);
    return out;
}

}  // namespace mvpl::test
