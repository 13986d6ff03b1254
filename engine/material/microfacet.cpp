#include "engine/material/microfacet.h"

namespace mvpl::material {

float ggx_lambda(const Vec3& w, float alpha) {
    const float c = std::max(w.z, kMinCos);
    return 0.5f * (ggx_stretched_length(w, alpha) / c - 1.0f);
}

float ggx_g1(const Vec3& w, float alpha) {
    const float c = std::max(w.z, 0.0f);
    const float denom = c + ggx_stretched_length(w, alpha);
    return denom > 0.0f ? 2.0f * c / denom : 0.0f;
}

float ggx_g2(const Vec3& wo, const Vec3& wi, float alpha) {
    // 2 cos θo cos θi / (cos θi A(wo) + cos θo A(wi)) is the same as 1 / (1 + Λo + Λi) without
    // the division by a cosine.
    const float co = std::max(wo.z, 0.0f);
    const float ci = std::max(wi.z, 0.0f);
    const float denom = ci * ggx_stretched_length(wo, alpha) + co * ggx_stretched_length(wi, alpha);
    return denom > 0.0f ? 2.0f * co * ci / denom : 0.0f;
}

Vec3 ggx_sample_visible_normal(const Vec3& wo, float alpha, const Vec2& u) {
    // Section 3.2: stretch the view direction to the hemisphere configuration (α = 1).
    const Vec3 vh = glm::normalize(Vec3(alpha * wo.x, alpha * wo.y, std::max(wo.z, kMinCos)));
    // Section 4.1: orthonormal basis around vh (any basis when vh = +z).
    const float len2 = vh.x * vh.x + vh.y * vh.y;
    const Vec3 t1 = len2 > 0.0f ? Vec3(-vh.y, vh.x, 0.0f) / std::sqrt(len2) : Vec3(1, 0, 0);
    const Vec3 t2 = glm::cross(vh, t1);
    // Section 4.2: uniform point on the projected disk, the half facing away from vh squashed.
    const float r = std::sqrt(u.x);
    const float phi = 2.0f * kPi * u.y;
    const float p1 = r * std::cos(phi);
    float p2 = r * std::sin(phi);
    const float s = 0.5f * (1.0f + vh.z);
    p2 = (1.0f - s) * safe_sqrt(1.0f - p1 * p1) + s * p2;
    // Section 4.3: reproject onto the hemisphere.
    const Vec3 nh = p1 * t1 + p2 * t2 + safe_sqrt(1.0f - p1 * p1 - p2 * p2) * vh;
    // Section 3.4: unstretch. nh is unit, so when its z is clamped to 0 its xy is not zero and the
    // normalisation is defined.
    return glm::normalize(Vec3(alpha * nh.x, alpha * nh.y, std::max(nh.z, 0.0f)));
}

float ggx_visible_normal_pdf(const Vec3& wo, const Vec3& h, float alpha) {
    if (wo.z <= 0.0f) return 0.0f;
    const float cos_oh = glm::dot(wo, h);
    if (cos_oh <= 0.0f || h.z <= 0.0f) return 0.0f;
    return ggx_g1(wo, alpha) * cos_oh * ggx_d(h, alpha) / std::max(wo.z, kMinCos);
}

float ggx_reflection_pdf(const Vec3& wo, const Vec3& wi, float alpha) {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    const std::optional<Vec3> h = reflection_half_vector(wo, wi);
    if (!h) return 0.0f;
    // wo·h = |wo + wi| / 2 > 0 here, so the max(0, wo·h) of D_wo is inactive and cancels against
    // the Jacobian 1 / (4 wo·h).
    return ggx_d(*h, alpha) / (2.0f * (wo.z + ggx_stretched_length(wo, alpha)));
}

std::optional<MicrofacetReflection> ggx_reflection(const Vec3& wo, const Vec3& wi, float alpha) {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return std::nullopt;
    const Vec3 r = shared::math::ggx_reflection(kLocalNormal, wo, wi, alpha);
    if (!(r.z > 0.0f)) return std::nullopt;
    return MicrofacetReflection{r.x, r.y};
}

std::optional<Vec3> reflection_half_vector(const Vec3& wo, const Vec3& wi) {
    const Vec3 sum = wo + wi;
    const float len2 = glm::dot(sum, sum);
    // The bound of shared::math::ggx_reflection (shading_math.h), which says why.
    if (!(len2 > 1e-30f)) return std::nullopt;
    return sum / std::sqrt(len2);
}

}  // namespace mvpl::material
