#pragma once
// One estimate's parameters, each given once: the image size, clamp, virtual-sphere radius,
// specular chains and sub-pixel positions in the GPU renderer's options, the seed and path depth
// in the sampler's. The CPU oracle, the clamping compensation, the caustic tracer and the
// Metropolis target take theirs from these (the functions below), so that no copy can disagree
// with the image it is added to.
#include <cstdint>
#include <string>

#include "engine/integrator/caustic_tracer.h"
#include "engine/integrator/clamp_compensation.h"
#include "engine/manylights/row_column_sampler.h"
#include "engine/reference/vpl_gather.h"
#include "engine/render/vpl_renderer.h"
#include "engine/sampler/sampler_factory.h"

namespace mvpl::integrator {

struct Estimate {
    std::string sampler = "mc";  // sampler::sampler_names()
    // The light paths: seed, tracer (max_depth, rr_depth) and the sampler's own options; its
    // width, height, clamp, vsl_radius and specular_chains are set from `render` (sampler()).
    sampler::SamplerSettings sampling;
    render::RenderOptions render;
    // Clamping compensation (integrator/clamp_compensation.h) on a CPU thread beside the shading:
    // `compensation_passes` samples per pixel, or 0: paced by the VPLs shaded
    // (cpu_estimator_thread.h).
    bool compensate = true;
    uint32_t compensation_passes = 0;
    // Caustics (integrator/caustic_tracer.h), paced as the compensation, where the scene has
    // vertices that leave no VPL; the light tracer then leaves no VPL on the chains' class.
    bool caustics = true;
    // Matrix row-column sampling (manylights/row_column_sampler.h): each pool of the stream's
    // VPLs shaded through weighted cluster representatives; off unless many_lights.pool > 0.
    manylights::RowColumnOptions many_lights;
};

// The sampler's settings with the image's size, clamp, virtual spheres and chains.
sampler::SamplerSettings sampler_settings(const Estimate& e);
// The CPU oracle's options: the GPU's sub-pixel positions, chains and interleaving.
reference::GatherOptions gather_options(const Estimate& e);
// The compensation's: compensated where the VPLs light, at the chains' rough ends.
CompensationOptions compensation_options(const Estimate& e);
// The caustic tracer's: the chains' class, and the compensation's share of near vertices when
// it runs beside.
CausticOptions caustic_options(const Estimate& e);
// Row-column sampling's rows and matrix: the image, clamp, spheres, chains and seed (the scene,
// BVH and camera are the caller's to set).
manylights::RowColumnContext row_column_context(const Estimate& e);

}  // namespace mvpl::integrator
