#include "tools/preview/preview_estimate.h"

#include "engine/core/subpixel.h"
#include "engine/light/specular_chain.h"
#include "engine/render/batch_plan.h"

namespace mvpl::preview {

render::RenderOptions preview_render_options(const PreviewOptions& options,
                                             const scene::Scene& scene, float clamp, uint32_t width,
                                             uint32_t height) {
    render::RenderOptions ro = options.levers;
    ro.width = width;
    ro.height = height;
    ro.shadow_resolution = options.shadow_resolution;
    ro.batch = options.batch;
    ro.jitter = options.jitter;
    ro.subpixel_rotation = subpixel_rotation(options.seed);  // as `mvpl render --seed`
    ro.clamp = clamp;
    ro.kept_shadow_bytes = options.kept_shadow_bytes;
    ro.chains.max_depth = options.max_depth;
    ro.chain_seed = options.seed;
    if (options.interleave_auto && (light::scene_may_chain(scene, ro.chains) ||
                                    uint64_t(ro.width) * ro.height < options.interleave_min_pixels))
        ro.interleave = 1;
    if (options.batches_per_position_auto)
        ro.batches_per_position = render::default_batches_per_position(scene.triangle_count());
    return ro;
}

integrator::Estimate preview_estimate(const PreviewOptions& options,
                                      const render::RenderOptions& ro, const std::string& sampler) {
    integrator::Estimate e;
    e.sampler = sampler;
    e.sampling.seed = options.seed;
    e.sampling.tracer.max_depth = options.max_depth;
    e.sampling.per_path = options.per_path;
    e.sampling.metropolis_per_path = options.metropolis_per_path;
    e.many_lights = options.many_lights;
    e.render = ro;
    e.compensate = options.compensate;
    e.compensation_passes = options.compensation_passes;
    e.caustics = options.caustics;
    return e;
}

}  // namespace mvpl::preview
