// A closure's parameters limited to the glTF ranges, and its type, written once for C++
// (engine/material/closure.h: clamp_to_valid_ranges, closure_type; the spec-gloss node) and GLSL
// (glsl_library.cpp, "clamp_closure", which every closure node returns through). NaN becomes the
// lower bound; 1e6 only keeps infinities out of the parameters that may exceed 1 (closure.h).
// Common subset as in shading_math.h.
#ifndef MVPL_SHADERS_SHARED_CLOSURE_RANGES_H
#define MVPL_SHADERS_SHARED_CLOSURE_RANGES_H

#ifdef __cplusplus
#include <glm/glm.hpp>

#include <cstdint>

#include "shaders/shared/shading_constants.h"

namespace mvpl::shared::math {
using uint = std::uint32_t;
using glm::min;
#endif

// [0, 1].
MVPL_INLINE float clamp_unit(float x) {
    return x > 0.0f ? min(x, 1.0f) : 0.0f;
}

// [0, 1e6].
MVPL_INLINE float clamp_non_negative(float x) {
    return x > 0.0f ? min(x, 1e6f) : 0.0f;
}

// ClosureType (engine/material/closure.h) of clamped parameters, the narrowest whose evaluator
// gives Bsdf::eval: Lambertian 0 (metallic and specular 0), conductor 1, dielectric 2,
// metal-rough 3.
MVPL_INLINE uint closure_type_of(float metallic, float specular) {
    if (metallic <= 0.0f && specular <= 0.0f) return 0u;
    if (metallic >= 1.0f) return 1u;
    if (metallic <= 0.0f) return 2u;
    return 3u;
}

#ifdef __cplusplus
}  // namespace mvpl::shared::math
#endif

#endif
