#pragma once
// Shared pieces of the sampler tests: small scenes and an oracle estimate with its standard error.
#include <vector>

#include "engine/core/image.h"
#include "engine/sampler/monte_carlo_sampler.h"
#include "engine/scene/scene.h"

namespace mvpl::test {

// A 4×4 Lambertian plane (albedo 0.6, y = 0, facing +y) under a one-sided emissive square facing
// down, seen from above; the light is outside the view.
scene::Scene area_lit_plane();

// The oracle image averaged over `batches` independent VPL sets (seeds seed, seed+1, …), each
// from options.paths paths, and the per-pixel standard error of that average (from the spread
// of the batches: s/√batches). jitter: the oracle's sub-pixel positions (the renderer's default
// schedule, the same positions in every batch); false: pixel centres.
struct BatchedImage {
    Image mean;
    Image standard_error;
    std::vector<Image> batches;
};
BatchedImage batched_oracle(const scene::Scene& scene, sampler::MonteCarloOptions options,
                            int batches, int resolution, int max_depth, bool jitter = true);

// Mean over the image of each channel's per-batch means: its standard error.
Rgb mean_standard_error(const BatchedImage& b);

}  // namespace mvpl::test
