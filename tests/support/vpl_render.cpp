#include "tests/support/vpl_render.h"

#include "engine/light/light_sampler.h"
#include "engine/reference/vpl_gather.h"
#include "engine/render/vpl_renderer.h"
#include "engine/sampler/monte_carlo_sampler.h"
#include "engine/trace/accel.h"

namespace mvpl::test {

light::VplSet monte_carlo_vpls(const scene::Scene& scene, uint64_t paths, int max_depth,
                               uint64_t seed) {
    const trace::Accel accel(scene);
    const light::LightSampler lights(scene);
    sampler::MonteCarloOptions o;
    o.paths = paths;
    o.seed = seed;
    o.tracer.max_depth = max_depth;
    return sampler::MonteCarloSampler(scene, accel, lights).generate(o);
}

Image gpu_render(gpu::Context& context, const scene::Scene& scene, const light::VplSet& vpls,
                 const VplRenderSettings& settings) {
    const trace::Accel accel(scene);
    render::VplRenderer renderer(context, scene, &accel);
    render::RenderOptions o;
    o.width = o.height = uint32_t(settings.res);
    o.shadow_resolution = uint32_t(settings.shadow_res);
    o.batch = uint32_t(settings.batch);
    o.clamp = settings.clamp;
    o.vsl_radius = settings.vsl_radius;
    o.shadows = settings.shadows;
    o.jitter = settings.jitter;
    o.chains.max_roughness = settings.chain_roughness;
    o.chains.max_depth = settings.chain_max_depth;
    o.chains.emission_samples = settings.chain_emission_samples;
    o.chain_seed = settings.chain_seed;
    o.interleave = uint32_t(settings.interleave);
    return renderer.render(vpls, o);
}

Image oracle_render(const scene::Scene& scene, const light::VplSet& vpls,
                    const VplRenderSettings& settings) {
    const trace::Accel accel(scene);
    reference::GatherOptions o;
    o.width = o.height = settings.res;
    o.clamp = settings.clamp;
    o.vsl_radius = settings.vsl_radius;
    o.subpixel = {settings.jitter, uint64_t(settings.batch)};
    o.chains.max_roughness = settings.chain_roughness;
    o.chains.max_depth = settings.chain_max_depth;
    o.chains.emission_samples = settings.chain_emission_samples;
    o.chain_seed = settings.chain_seed;
    o.interleave = settings.interleave;
    return reference::gather_vpls(scene, accel, vpls, o);
}

}  // namespace mvpl::test

namespace mvpl::test {

Image emission_at_positions(const scene::Scene& scene, size_t vpl_count,
                            const VplRenderSettings& settings) {
    const trace::Accel accel(scene);
    reference::GatherOptions o;
    o.width = o.height = settings.res;
    o.subpixel = {settings.jitter, uint64_t(settings.batch)};
    o.first_vpl = vpl_count;  // no VPL of its own: the emission over the positions of vpl_count
    return reference::gather_vpls(scene, accel, {}, o);
}

}  // namespace mvpl::test
