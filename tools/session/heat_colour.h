#pragma once
// The colour ramp of the preview's error heat map and of the VPL dots: blue → green → yellow →
// red over the thirds of t ∈ [0, 1] (clamped). Each colour has a channel at exactly 0 and one at
// exactly 1, which no picture's radiance is likely to repeat.
#include <algorithm>

#include "engine/core/color.h"

namespace mvpl::session {

inline Rgb heat_colour(float t) {
    t = std::clamp(t, 0.0f, 1.0f);
    if (t < 1.0f / 3.0f) return Rgb(0.0f, 3.0f * t, 1.0f - 3.0f * t);
    if (t < 2.0f / 3.0f) return Rgb(3.0f * t - 1.0f, 1.0f, 0.0f);
    return Rgb(1.0f, 3.0f - 3.0f * t, 0.0f);
}

}  // namespace mvpl::session
