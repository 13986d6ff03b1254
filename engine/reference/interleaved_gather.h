#pragma once
// The CPU oracle's interleaved sampling (shaders/shared/interleave.h), so that a GPU image
// rendered with `--interleave K` can be checked pixel by pixel: per sub-pixel position, each
// pixel's class share of the position's VPLs (times K²) with exact Embree visibility, then the
// same geometry-aware filter as interleave_filter.comp over the first hits of that position's
// camera rays. With specular chains (`lights` given: the scene may chain), a glossy pixel is
// shaded at its chain's rough end, filtered with the compatible chained neighbours and weighted
// by its own throughput, as interleave_filter.comp does with the chain layer's records.
// gather_vpls calls it when GatherOptions::interleave > 1.
#include <vector>

#include "engine/core/image.h"
#include "engine/light/vpl_contribution.h"
#include "engine/reference/vpl_gather.h"
#include "engine/scene/scene.h"
#include "engine/trace/accel.h"

namespace mvpl::light {
class LightSampler;
}

namespace mvpl::reference {

// Σ over the list's VPLs, interleaved and filtered, unscaled (no emission); d_min2 = d_min².
// lights: the scene's light sampler where it may chain (light::scene_may_chain), else nullptr.
Image interleaved_vpl_sum(const scene::Scene& scene, const trace::Accel& accel,
                          const std::vector<light::PreparedVpl>& vpls, const GatherOptions& options,
                          float d_min2, const light::LightSampler* lights = nullptr);

}  // namespace mvpl::reference
