// The constants of the shading mathematics (shading_math.h, lambertian.h, closure_eval.h), for
// C++ and GLSL: a shader that evaluates only Lambertian closures needs these and lambertian.h.
// MVPL_INLINE marks the functions of those headers (inline in C++, nothing in GLSL);
// MVPL_NORMAL is the type of their shading normal: GLSL's world-space vec3, C++'s LocalNormal,
// the z axis of its local frame (shading_math.h).
#ifndef MVPL_SHADERS_SHARED_SHADING_CONSTANTS_H
#define MVPL_SHADERS_SHARED_SHADING_CONSTANTS_H

#ifdef __cplusplus
#define MVPL_INLINE inline
#define MVPL_NORMAL LocalNormal
namespace mvpl::shared::math {
#else
#define MVPL_INLINE
#define MVPL_NORMAL vec3
#endif

const float kPi = 3.14159265358979323846f;
const float kInvPi = 0.31830988618379067154f;
// Smallest GGX alpha evaluated, and the smallest cosine inside the microfacet terms: why these
// values, engine/material/microfacet.h.
const float kMinAlpha = 1e-4f;
const float kMinCos = 1e-7f;

#ifdef __cplusplus
}  // namespace mvpl::shared::math
#endif

#endif
