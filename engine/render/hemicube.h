#pragma once
// Hemicubes for VPLs that light one hemisphere (Area and Surface: max(0, n·ω)): of each face of
// the world-aligned shadow cube only the texels whose directions can reach the lit side of the
// VPL's plane are drawn (a render area; Cohen & Greenberg 1985's hemicube is one full face and
// four half faces, which is what an axis-aligned normal gets here). The shading pass reads a
// cube texel only for a receiver with n·ω > 0 (shadow_lookup.glsl), or its junction lookup
// up to about a texel beyond that, so a margin of kHemicubeMargin texels keeps every texel it
// can read. The cube stays world-aligned, so the lookup does not change.
#include <cstdint>
#include <optional>

#include "engine/core/math.h"

namespace mvpl::render {

// Texels of margin around the lit part of a face.
constexpr uint32_t kHemicubeMargin = 2;

struct FaceRect {
    uint32_t x = 0;  // first column and row
    uint32_t y = 0;
    uint32_t width = 0;
    uint32_t height = 0;
};

// The texels of cube face `face` (+X −X +Y −Y +Z −Z, shadow.vert's projection) of side `res`
// whose directions ω may have n·ω ≥ −1e-3 · |ω|∞, grown by kHemicubeMargin and clamped to the
// face; nothing when no direction through the face does (the whole face lies behind).
std::optional<FaceRect> lit_face_rect(const Vec3& n, uint32_t face, uint32_t res);

}  // namespace mvpl::render
