#pragma once
// The orthographic shadow map of a directional VPL: a square window perpendicular to the
// direction of travel that covers the scene bounds, and the depth range along the direction.
// The shadow pass renders with it and the shading pass looks up with it (both read the same
// floats, via push constants and the VPL record), so the texel a point renders into is the texel
// it reads.
#include "engine/core/math.h"
#include "engine/scene/bounds.h"

namespace mvpl::render {

struct DirectionalFrame {
    Vec3 u{1, 0, 0};      // map x axis
    Vec3 v{0, 1, 0};      // map y axis
    Vec3 dir{0, 0, 1};    // unit direction of travel
    Vec3 origin{0.0f};    // (u, v, w) of the map's corner and of its nearest depth
    float extent = 1.0f;  // side of the square window, world units
    float depth = 1.0f;   // depth range along dir, world units
};

// direction: the VPL's direction of travel (need not be unit).
DirectionalFrame directional_frame(const Vec3& direction, const scene::Bounds& bounds);

}  // namespace mvpl::render
