#pragma once
// The VPL pipeline in one call each, for tests that compare its stages: Monte Carlo light paths,
// the GPU renderer and the CPU oracle over the same VPLs.
#include <cstdint>
#include <vector>

#include "engine/core/image.h"
#include "engine/light/virtual_sphere.h"
#include "engine/light/vpl.h"
#include "engine/scene/scene.h"

namespace mvpl::gpu {
class Context;
}

namespace mvpl::test {

// VPLs of `paths` Monte Carlo light paths (every VPL of a path kept; scale 1/paths).
light::VplSet monte_carlo_vpls(const scene::Scene& scene, uint64_t paths, int max_depth,
                               uint64_t seed);

struct VplRenderSettings {
    int res = 64;          // square image
    int shadow_res = 128;  // cube face side
    float clamp = 0.05f;   // fraction of the scene diagonal; 0: off
    // Virtual spherical lights (light/virtual_sphere.h), fraction of the diagonal; 0: off.
    float vsl_radius = light::kDefaultVslRadius;
    bool shadows = true;
    int batch = 32;
    bool jitter = true;  // a sub-pixel position per batch, the same in both renderers
    // Specular chains (light/specular_chain.h), the same in both renderers; roughness < 0: off.
    float chain_roughness = -1.0f;
    int chain_max_depth = -1;
    int chain_emission_samples = 1;  // ChainOptions::emission_samples
    uint64_t chain_seed = 0;
    int interleave = 1;  // interleaved sampling (RenderOptions::interleave), in both renderers
};

// The GPU renderer's image of `vpls` seen by the scene camera.
Image gpu_render(gpu::Context& context, const scene::Scene& scene, const light::VplSet& vpls,
                 const VplRenderSettings& settings);
// The emitted radiance seen directly in an image of `vpl_count` VPLs rendered with `settings`:
// averaged over the sub-pixel positions such an image takes (the oracle's rays; the GPU's
// rasteriser agrees but for positions within 1/256 pixel of an edge). It is the term of
// gpu_render and oracle_render that is not VPL light, for tests that swap it for a box filter.
Image emission_at_positions(const scene::Scene& scene, size_t vpl_count,
                            const VplRenderSettings& settings);
// The CPU oracle's image of the same VPLs (exact visibility; settings.shadow_res unused).
Image oracle_render(const scene::Scene& scene, const light::VplSet& vpls,
                    const VplRenderSettings& settings);

}  // namespace mvpl::test
