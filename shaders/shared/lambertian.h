// Lambertian reflection f = ρ/π of a closure with no specular layer, written once for C++
// (engine/material/lambertian.h, in the local frame's n = (0, 0, 1)) and GLSL (glsl_library.cpp,
// "lambertian_eval"): zero unless both directions are above the shading normal n. The common
// subset and its rules are shading_math.h's; this file alone comes with shading_constants.h into a
// shader whose closures are all Lambertian.
#ifndef MVPL_SHADERS_SHARED_LAMBERTIAN_H
#define MVPL_SHADERS_SHARED_LAMBERTIAN_H

#ifdef __cplusplus
#include "shaders/shared/shading_math.h"  // C++ only: its LocalNormal

namespace mvpl::shared::math {
#endif

// f of a pair known to be above n.
MVPL_INLINE vec3 lambertian_f(vec3 albedo) {
    return albedo * kInvPi;
}

MVPL_INLINE vec3 lambertian_reflection(vec3 albedo, MVPL_NORMAL n, vec3 wo, vec3 wi) {
    return dot(n, wo) > 0.0f && dot(n, wi) > 0.0f ? lambertian_f(albedo) : vec3(0.0f);
}

#ifdef __cplusplus
}  // namespace mvpl::shared::math
#endif

#endif
