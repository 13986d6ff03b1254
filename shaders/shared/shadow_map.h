// What a shadow texel holds: the shadow pass's cubes and orthographic maps
// (engine/render/shadow_pass.h) and the shading pass's tests
// (shaders/render/shading_template.glsl) read the same value.
#ifndef MVPL_SHADERS_SHARED_SHADOW_MAP_H
#define MVPL_SHADERS_SHARED_SHADOW_MAP_H

#include "prelude.h"

#ifdef __cplusplus
#include <algorithm>
#include <cmath>
#endif

MVPL_SHARED_BEGIN

#ifdef __cplusplus
using std::abs;
using std::floor;
using std::max;
#endif

// The distance a shadow texel holds where no surface was rendered.
const float kShadowNoOccluder = 3.0e38f;

// A simplified mesh may move the surface by this many texel footprints (d · 2 / resolution on a
// cube face, extent / resolution on an orthographic map): the shadow pass picks levels of detail
// within it and the shading pass's tests allow as much depth in front of a receiver for the
// texels such a mesh drew (their distance negated), so that a receiver on the full surface is not
// shadowed by its own coarser copy. A silhouette moves by at most a texel at a face's centre
// (three at its corners). One footprint rather than a quarter: the dragon draws 44 k instead of
// 85 k triangles per VPL (126 → 189 VPL/s) at 1.08× the full maps' error against the oracle
// (docs/results.md, "Closed interiors and the shadow levels of detail").
const float kLodFootprint = 1.0f;

// A texel's second channel: the plane of the surface it holds, so that the shading pass can tell
// an occluder that stands in front of a receiver from one that merely shares the receiver's texel
// beyond it (shadow_lookup.glsl, occluder_plane_passes_behind). The plane's normal n, whose sign
// does not matter, turned into the hemisphere n_z ≥ 0 and stored as the hemi-octahedral map of
// Cigolle et al. 2014 ("A Survey of Efficient Representations for Independent Unit Vectors",
// JCGT 3(2), §3.3): p = (n_x, n_y) / (|n_x| + |n_y| + n_z), (s, t) = (p_x + p_y, p_x − p_y) in
// [−1, 1]², each quantised to 12 bits (a step of 2/4095: at most 1.04·10⁻³ rad,
// tests/render/test_shadow_texel.cpp) and packed as the
// integer 1 + 4096 · q_s + q_t, which a float holds exactly (at most 2²⁴). 0: no plane (nothing
// drawn, or a triangle too small for its derivatives).
const float kNoOccluderPlane = 0.0f;
const float kPlaneLevels = 4095.0f;

#ifdef __cplusplus
#define MVPL_PLANE_FN inline
#else
#define MVPL_PLANE_FN
#endif

// The code of the plane with normal (x, y, z), any length above 0. One reciprocal and a select
// rather than a branch: the shadow pass evaluates it for every fragment (its first form, with two
// divisions and an early return, took 15 % of lavapipe's shadow pass on the Cornell box).
MVPL_PLANE_FN float occluder_plane_code(float x, float y, float z) {
    const float l1 = abs(x) + abs(y) + abs(z);
    const float scale = (z < 0.0f ? -0.5f : 0.5f) * kPlaneLevels / max(l1, 1e-30f);
    const float half_range = 0.5f * kPlaneLevels + 0.5f;
    const float qs = floor((x + y) * scale + half_range);
    const float qt = floor((x - y) * scale + half_range);
    return l1 > 0.0f ? 1.0f + 4096.0f * qs + qt : kNoOccluderPlane;
}

// The hemi-octahedral coordinates (s, t) of a code other than kNoOccluderPlane.
MVPL_PLANE_FN float occluder_plane_s(float code) {
    return floor((code - 1.0f) / 4096.0f) / kPlaneLevels * 2.0f - 1.0f;
}
MVPL_PLANE_FN float occluder_plane_t(float code) {
    const float c = code - 1.0f;
    return (c - 4096.0f * floor(c / 4096.0f)) / kPlaneLevels * 2.0f - 1.0f;
}

#undef MVPL_PLANE_FN

MVPL_SHARED_END

#endif
