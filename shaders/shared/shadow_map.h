// What a shadow texel holds: the shadow pass's cubes and orthographic maps
// (engine/render/shadow_pass.h) and the shading pass's tests
// (shaders/render/shading_template.glsl) read the same value.
#ifndef MVPL_SHADERS_SHARED_SHADOW_MAP_H
#define MVPL_SHADERS_SHARED_SHADOW_MAP_H

#include "prelude.h"

MVPL_SHARED_BEGIN

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

MVPL_SHARED_END

#endif
