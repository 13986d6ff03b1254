#pragma once
// Linear Rec.709 RGB radiometric quantities.
#include "engine/core/math.h"

namespace mvpl {

using Rgb = glm::vec3;

// Rec.709 / sRGB luminance weights.
inline float luminance(const Rgb& c) {
    return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
}
inline float max_component(const Rgb& c) {
    return std::max(c.r, std::max(c.g, c.b));
}
inline bool is_black(const Rgb& c) {
    return c.r == 0.0f && c.g == 0.0f && c.b == 0.0f;
}

}  // namespace mvpl
