#pragma once
// Mitsuba 0.6's `vpl` clamping as mvpl's clamp (issue 34). Mitsuba 0.6 (src/libhw/vpl.cpp,
// VPLShaderManager::setVPL, master 10af06f3) clamps each VPL's 1/d² at a distance of its own:
//   d_min = n + clamping · (f − n),   f = 1.5 · t_max,   n = max(t_min / 1.5, 10⁻⁵ · f),
// t_min and t_max the nearest and farthest hits of 250 rays from the VPL in the directions of a
// (0,2) sequence, cosine-distributed about its normal (over the sphere for a point light); where
// none hits, f = r_out + 2.25 r and n = max(r_out − 0.25 r, 10⁻⁵ f), r the radius of the scene's
// bounding sphere and r_out the VPL's distance outside it. mvpl clamps every VPL at one distance,
// clamp × the bounding-box diagonal (light/vpl.h), so the mapping is not exact: the clamp is the
// mean of Mitsuba's d_min over the VPLs of 256 light paths, in diagonals — the same distance on
// average, not per VPL (a VPL near other geometry is clamped less than Mitsuba clamps it, one in
// the open more). Rays stop at the first surface, glass included (Mitsuba continues through
// transmissive surfaces, up to 5 of them). Directional VPLs have no distance and no part in it.
#include <cstdint>

#include "engine/light/light_sampler.h"
#include "engine/light/vpl.h"
#include "engine/scene/scene.h"
#include "engine/trace/accel.h"

namespace mvpl::sampler {

// Mitsuba 0.6's d_min for `vpl` at `clamping` ∈ [0, 1]; negative for a directional VPL.
float mitsuba_min_distance(const light::Vpl& vpl, const scene::Scene& scene,
                           const trace::Accel& accel, float clamping);

// The --clamp (a fraction of the diagonal, in [0, 1]) whose distance is the mean of
// mitsuba_min_distance over the VPLs of light paths traced to `max_depth` (Mitsuba's maxDepth)
// with a fixed seed; light::kDefaultClamp when the scene leaves no VPL that has a distance.
float mitsuba_clamp(const scene::Scene& scene, const trace::Accel& accel,
                    const light::LightSampler& lights, float clamping, int max_depth);

}  // namespace mvpl::sampler
