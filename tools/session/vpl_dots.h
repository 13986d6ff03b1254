#pragma once
// VPLs as dots over a picture, for `mvpl vpls` and the preview's `vpls` view: each VPL that
// `project` places on the film (pixel coordinates) becomes a dot whose area grows with its power
// relative to the largest, at least a pixel wide, coloured by that power on the heat map's ramp
// (heat_colour.h): red the largest, yellow 10⁻¹ of it, green 10⁻², blue 10⁻³ and below. Emitter
// VPLs carry a white ring.
#include <cstddef>
#include <functional>
#include <vector>

#include "engine/core/image.h"
#include "engine/core/math.h"
#include "engine/light/vpl.h"

namespace mvpl::session {

inline const Rgb kEmitterRing{1.0f, 1.0f, 1.0f};

// The dot's colour of a VPL with `power` relative to the largest (luminance ratio in [0, 1]).
Rgb dot_colour(float relative_power);

// How many were drawn. Directional VPLs (no position) are left out.
size_t draw_vpls(Image& image, const std::function<bool(const Vec3&, Vec2&)>& project,
                 const std::vector<light::Vpl>& vpls);

}  // namespace mvpl::session
