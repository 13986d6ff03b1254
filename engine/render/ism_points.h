#pragma once
// The scene points of imperfect shadow maps (Ritschel et al. 2008, section 3.1): a fixed set
// sampled once, uniformly by area over the shadow casters' triangles, which every imperfect map
// splats instead of drawing the triangles (ism_pass.h). CPU only and Vulkan-free (the tests
// check the density).
#include <cstdint>
#include <vector>

#include "engine/render/shadow_clusters.h"
#include "shaders/shared/ism.h"

namespace mvpl::render {

using shared::IsmPoint;

// `count` points (none if the casters have no area), the i-th in the i-th of `count` equal
// slices of the total area in triangle order (stratified, so that no triangle of area A gets
// fewer than ⌊count · A / total⌋ − 1 points), each a disc of the radius that gives it 1/count of
// the area (IsmPoint::radius), with a seed of its own so that the set is the same
// on every run.
std::vector<IsmPoint> sample_ism_points(const ShadowClusters& casters, uint32_t count,
                                        uint64_t seed = 0);

}  // namespace mvpl::render
