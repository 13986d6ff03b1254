#pragma once
// Isotropic GGX / Trowbridge-Reitz microfacet distribution (Walter et al. 2007, "Microfacet Models
// for Refraction through Rough Surfaces") with the height-correlated Smith masking-shadowing
// function (Heitz 2014, "Understanding the Masking-Shadowing Function in Microfacet-Based BRDFs")
// and sampling of the distribution of visible normals (Heitz 2018, "Sampling the GGX Distribution
// of Visible Normals"). Local shading frame: z is the normal, every direction is unit length.
//
// Every function is written so that it ports 1:1 to GLSL (no tables, no branches on data other
// than guards) and never divides by a cosine that can reach zero.
#include <optional>

#include "engine/core/math.h"
#include "shaders/shared/shading_math.h"

namespace mvpl::material {

// Smallest GGX alpha (= roughness²) we evaluate; roughness below 0.01 behaves as 0.01.
// Why 1e-4: the peak of D is 1/(π α²) ≈ 3.2e7 and, since A(wo) ≥ α below, the reflection pdf
// D / (2 (cos θo + A(wo))) never exceeds 1/(2π α³) ≈ 1.6e11, even at grazing wo, so the squared
// pdfs of MIS's power heuristic (≈ 2.5e22) stay far from float overflow. More importantly the lobe
// is then ~1e-4 rad wide, three orders of magnitude wider than the angular rounding error of a
// half vector normalize(wo + wi) computed in float (~1e-7 rad), so eval(wo, sample().wi)
// reproduces the density that the sampler drew from — on the CPU and on the GPU alike. A lobe of
// 1e-4 rad (0.006°) is a mirror for any image this renderer makes.
// (shaders/shared/shading_math.h holds the value, for C++ and GLSL.)
using shared::math::kMinAlpha;

// Cosines below this are treated as this value inside the microfacet terms, so that the
// visibility term V below (≤ 1 / (4 kMinCos · kMinAlpha)) stays finite at the horizon.
using shared::math::kMinCos;

using shared::math::roughness_to_alpha;

// The local frame's normal z, as the shared functions take it (shading_math.h).
using shared::math::kLocalNormal;

// D(h) = α² / (π (h.x² + h.y² + α² h.z²)²), which is Walter et al. eq. 33 rewritten for a unit h
// without tan θ, so that h = n (tan θ = 0) and h at the horizon (cos θ = 0) need no special case
// and 1 − cos² θ never cancels catastrophically for small α.
inline float ggx_d(const Vec3& h, float alpha) {
    return shared::math::ggx_d(kLocalNormal, h, alpha);
}

// √(cos² θ + α² sin² θ): the length of the direction stretched by α (Heitz 2018, sec. 3.2). It is
// the one expression that Λ, G1 and the visibility term share.
inline float ggx_stretched_length(const Vec3& w, float alpha) {
    return shared::math::ggx_stretched_length(kLocalNormal, w, alpha);
}

// Smith Λ for GGX (Heitz 2014, eq. 72): Λ = (√(1 + α² tan² θ) − 1) / 2, evaluated as
// (A / cos θ − 1) / 2 with A the stretched length. Requires w.z > 0.
float ggx_lambda(const Vec3& w, float alpha);
// G1(w) = 1 / (1 + Λ(w)) = 2 cos θ / (cos θ + A): finite and in [0, 1] for any w.z ≥ 0.
float ggx_g1(const Vec3& w, float alpha);
// Height-correlated Smith G2 = 1 / (1 + Λ(wo) + Λ(wi)) (Heitz 2014, eq. 99); both directions
// above the surface.
float ggx_g2(const Vec3& wo, const Vec3& wi, float alpha);
// The specular "visibility" V = G2 / (4 cos θo cos θi) in the division-safe form
// V = 0.5 / (cos θi A(wo) + cos θo A(wi)) (multiply numerator and denominator of
// 1/(1 + Λo + Λi) by 2 cos θo cos θi). Cosines are clamped at kMinCos.
inline float ggx_visibility(const Vec3& wo, const Vec3& wi, float alpha) {
    return shared::math::ggx_visibility(kLocalNormal, wo, wi, alpha);
}

// Heitz 2018, listing 1: a microfacet normal distributed as the visible normals seen from wo,
// D_wo(h) = G1(wo) max(0, wo·h) D(h) / cos θo. Requires wo.z > 0; h.z ≥ 0.
Vec3 ggx_sample_visible_normal(const Vec3& wo, float alpha, const Vec2& u);
// D_wo(h) itself (Heitz 2018, eq. 3).
float ggx_visible_normal_pdf(const Vec3& wo, const Vec3& h, float alpha);
// Solid-angle density of wi = reflect(wo, h) with h ~ D_wo: D_wo(h) / (4 wo·h) (Walter et al.
// eq. 14), simplified with G1 = 2 cos θo / (cos θo + A(wo)) to D(h) / (2 (cos θo + A(wo))).
// 0 unless both directions are above the surface.
float ggx_reflection_pdf(const Vec3& wo, const Vec3& wi, float alpha);

// The two quantities a microfacet reflection lobe needs for a pair of directions: D(h)·V (with
// V = G2 / (4 cos θo cos θi) as above) and the Fresnel cosine wo·h (= wi·h), where
// h = normalize(wo + wi).
struct MicrofacetReflection {
    float dv = 0.0f;
    float cos_oh = 0.0f;
};
// nullopt unless both directions are above the surface and h is defined.
std::optional<MicrofacetReflection> ggx_reflection(const Vec3& wo, const Vec3& wi, float alpha);

// The half vector normalize(wo + wi) of a reflection, or nullopt when it is degenerate
// (wo = −wi, or both so close to the horizon that the sum underflows).
std::optional<Vec3> reflection_half_vector(const Vec3& wo, const Vec3& wi);

// Mirror wo about the (unit) microfacet normal h.
inline Vec3 reflect_about(const Vec3& wo, const Vec3& h) {
    return 2.0f * glm::dot(wo, h) * h - wo;
}

}  // namespace mvpl::material
