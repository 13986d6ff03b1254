#pragma once
// The colour ramp of the preview's error heat map and of the VPL dots: blue → green → yellow →
// red over the thirds of t ∈ [0, 1] (clamped): (0, g, 1 − g), then (r, 1, 0), then (1, g, 0),
// a pattern no picture's radiance is likely to repeat (on_heat_ramp).
#include <algorithm>
#include <cmath>

#include "engine/core/color.h"

namespace mvpl::session {

inline Rgb heat_colour(float t) {
    t = std::clamp(t, 0.0f, 1.0f);
    if (t < 1.0f / 3.0f) return Rgb(0.0f, 3.0f * t, 1.0f - 3.0f * t);
    if (t < 2.0f / 3.0f) return Rgb(3.0f * t - 1.0f, 1.0f, 0.0f);
    return Rgb(1.0f, 3.0f - 3.0f * t, 0.0f);
}

// Whether c is a colour of heat_colour (to rounding).
inline bool on_heat_ramp(const Rgb& c) {
    const bool in_range = std::min({c.r, c.g, c.b}) >= 0.0f && std::max({c.r, c.g, c.b}) <= 1.0f;
    const bool first = c.r == 0.0f && std::abs(c.g + c.b - 1.0f) < 1e-6f;
    return in_range && (first || (c.b == 0.0f && (c.g == 1.0f || c.r == 1.0f)));
}

}  // namespace mvpl::session
