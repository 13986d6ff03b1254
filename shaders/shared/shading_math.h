// The shading mathematics that C++ and GLSL both evaluate, written once: Schlick's Fresnel
// (Schlick 1994, as glTF 2.0 Appendix B uses it), the dielectric's normal-incidence reflectance
// (KHR_materials_ior) and the isotropic GGX distribution with the height-correlated Smith
// visibility (Walter et al. 2007; Heitz 2014) in the form that needs no division by a cosine.
// Directions are unit vectors about the shading normal n (MVPL_NORMAL, shading_constants.h): the
// CPU passes its local frame's n = (0, 0, 1), kLocalNormal below, whose dot and cross are the
// components they reduce to exactly (w.z; w.x² + w.y² for the sine) without the multiplications
// by 0 that a vec3 (0, 0, 1) would cost; the GPU passes the world-space normal (the cross product
// keeps the small sines of glossy lobes free of the cancellation in 1 − cos²).
// engine/material/microfacet.h and fresnel.h give C++ its local-frame names;
// engine/material/glsl_library.cpp emits this file's text into the shaders that evaluate closures,
// after shading_constants.h.
//
// Written in the common subset: float literals with f, functions MVPL_INLINE (inline in C++), no
// out parameters, GLSL's built-in names (glm's in C++); C++-only code in `#ifdef __cplusplus`
// blocks, which the template expansion drops (engine/render/shader_program.cpp) and glslang skips.
#ifndef MVPL_SHADERS_SHARED_SHADING_MATH_H
#define MVPL_SHADERS_SHARED_SHADING_MATH_H

#ifdef __cplusplus
#include <glm/glm.hpp>

#include "shaders/shared/shading_constants.h"

namespace mvpl::shared::math {
using vec3 = glm::vec3;
using glm::abs;
using glm::clamp;
using glm::cross;
using glm::dot;
using glm::max;
using glm::min;
using glm::sqrt;

// The z axis of a local shading frame (engine/core/math.h, Frame::to_local).
struct LocalNormal {};
inline constexpr LocalNormal kLocalNormal{};
// glm::dot(vec3(0, 0, 1), w) and glm::cross(vec3(0, 0, 1), w) for finite w, bit for bit.
inline float dot(LocalNormal, vec3 w) {
    return w.z;
}
inline vec3 cross(LocalNormal, vec3 w) {
    return vec3(-w.y, w.x, 0.0f);
}
#endif

// (1 − |cos|)^5, glTF's `fresnel_w`.
MVPL_INLINE float schlick_weight(float cos_theta) {
    const float m = clamp(1.0f - abs(cos_theta), 0.0f, 1.0f);
    const float m2 = m * m;
    return m2 * m2 * m;
}

// F = F0 + (F90 − F0)(1 − |cos|)^5.
MVPL_INLINE vec3 fresnel_schlick(vec3 f0, vec3 f90, float cos_theta) {
    return f0 + (f90 - f0) * schlick_weight(cos_theta);
}
MVPL_INLINE float fresnel_schlick(float f0, float f90, float cos_theta) {
    return f0 + (f90 - f0) * schlick_weight(cos_theta);
}

// ((ior − 1) / (ior + 1))² against air. KHR_materials_specular uses ior = 0 as "F0 = 1";
// negative values are outside the extension's schema and are treated as 0.
MVPL_INLINE float f0_from_ior(float ior) {
    const float n = max(ior, 0.0f);
    const float r = (n - 1.0f) / (n + 1.0f);
    return r * r;
}

MVPL_INLINE float roughness_to_alpha(float roughness) {
    const float r = clamp(roughness, 0.0f, 1.0f);
    return max(r * r, kMinAlpha);
}

// |n × w|² = sin² of the angle between n and w.
MVPL_INLINE float sin2_about(MVPL_NORMAL n, vec3 w) {
    const vec3 c = cross(n, w);
    return dot(c, c);
}

// D(h) = α² / (π (sin² θh + α² cos² θh)²): Walter et al. eq. 33 without tan θ, so that h = n and
// h at the horizon need no special case.
MVPL_INLINE float ggx_d(MVPL_NORMAL n, vec3 h, float alpha) {
    const float a2 = alpha * alpha;
    const float hz = dot(n, h);
    const float denom = sin2_about(n, h) + a2 * hz * hz;
    if (!(denom > 0.0f)) return 0.0f;
    return a2 / (kPi * denom * denom);
}

// √(cos² θ + α² sin² θ): the direction stretched by α (Heitz 2018, sec. 3.2), which Λ, G1 and
// the visibility term share.
MVPL_INLINE float ggx_stretched_length(MVPL_NORMAL n, vec3 w, float alpha) {
    const float z = dot(n, w);
    return sqrt(z * z + alpha * alpha * sin2_about(n, w));
}

// V = G2 / (4 cos θo cos θi) = 0.5 / (cos θi A(wo) + cos θo A(wi)) with the height-correlated
// Smith G2 (Heitz 2014, eq. 99); cosines clamped at kMinCos, so it stays finite at the horizon.
MVPL_INLINE float ggx_visibility(MVPL_NORMAL n, vec3 wo, vec3 wi, float alpha) {
    const float co = max(dot(n, wo), kMinCos);
    const float ci = max(dot(n, wi), kMinCos);
    return 0.5f /
           (ci * ggx_stretched_length(n, wo, alpha) + co * ggx_stretched_length(n, wi, alpha));
}

// The microfacet reflection of the pair (wo, wi): (D·V, wo·h, 1) with h = normalize(wo + wi), or
// (0, 0, 0) where h is undefined (wo = −wi, or a sum that underflows: 1e-30 keeps 1/√len2 well
// inside the float range, and only pairs within ~1e-15 of wo = −wi land there).
MVPL_INLINE vec3 ggx_reflection(MVPL_NORMAL n, vec3 wo, vec3 wi, float alpha) {
    const vec3 sum = wo + wi;
    const float len2 = dot(sum, sum);
    if (!(len2 > 1e-30f)) return vec3(0.0f);
    const vec3 h = sum / sqrt(len2);
    return vec3(ggx_d(n, h, alpha) * ggx_visibility(n, wo, wi, alpha),
                clamp(dot(wo, h), 0.0f, 1.0f), 1.0f);
}

#ifdef __cplusplus
}  // namespace mvpl::shared::math
#endif

#endif
