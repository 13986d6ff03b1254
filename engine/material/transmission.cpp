#include "engine/material/transmission.h"

#include "engine/material/microfacet.h"

namespace mvpl::material {

namespace {

// sin² of the transmitted angle for a facet cosine c (Snell's law).
float sin2_transmitted(float c, const Interface& side) {
    const float eta = side.eta_o / side.eta_t;
    return eta * eta * std::max(0.0f, 1.0f - c * c);
}

}  // namespace

Rgb interface_fresnel(const DielectricLayer& layer, float cos_oh, const Interface& side,
                      float cos_thin) {
    const float c = std::clamp(cos_oh, 0.0f, 1.0f);
    if (side.thin() || side.eta_o <= side.eta_t) return dielectric_fresnel(layer, c);
    if (cos_thin >= 0.0f) return dielectric_fresnel(layer, std::min(cos_thin, 1.0f));
    // From the denser side Schlick takes the cosine of the transmitted (thinner-side) angle.
    const float s2 = sin2_transmitted(c, side);
    if (s2 >= 1.0f) return Rgb(1.0f);
    return dielectric_fresnel(layer, std::sqrt(1.0f - s2));
}

std::optional<Vec3> refract_about(const Vec3& wo, const Vec3& h, const Interface& side) {
    const float c = glm::dot(wo, h);
    if (!(c > 0.0f)) return std::nullopt;
    const float s2 = sin2_transmitted(c, side);
    if (s2 >= 1.0f) return std::nullopt;
    const float eta = side.eta_o / side.eta_t;
    // pbrt-v3 §8.2.3 with the incident direction −wo.
    const Vec3 wi = -eta * wo + (eta * c - std::sqrt(1.0f - s2)) * h;
    return glm::normalize(wi);
}

std::optional<Vec3> transmission_half_vector(const Vec3& wo, const Vec3& wi,
                                             const Interface& side) {
    if (!(wo.z > 0.0f) || !(wi.z < 0.0f)) return std::nullopt;
    if (side.thin()) return reflection_half_vector(wo, mirror_z(wi));
    Vec3 h = -(side.eta_o * wo + side.eta_t * wi);
    const float len2 = glm::dot(h, h);
    if (!(len2 > 1e-30f)) return std::nullopt;
    h /= std::sqrt(len2);
    if (h.z < 0.0f) h = -h;
    // A refraction about h has wo in front of the facet and wi behind it.
    if (!(glm::dot(wo, h) > 0.0f) || !(glm::dot(wi, h) < 0.0f)) return std::nullopt;
    return h;
}

std::optional<MicrofacetTransmission> ggx_transmission(const Vec3& wo, const Vec3& wi, float alpha,
                                                       const Interface& side) {
    if (side.thin()) {
        if (!(wi.z < 0.0f)) return std::nullopt;
        const std::optional<MicrofacetReflection> r = ggx_reflection(wo, mirror_z(wi), alpha);
        if (!r) return std::nullopt;
        return MicrofacetTransmission{r->dv, r->cos_oh, r->cos_oh};
    }
    const std::optional<Vec3> h = transmission_half_vector(wo, wi, side);
    if (!h) return std::nullopt;
    const float cos_oh = glm::dot(wo, *h);
    const float cos_ih = -glm::dot(wi, *h);
    const float denom = side.eta_o * cos_oh - side.eta_t * cos_ih;
    if (!(std::abs(denom) > 0.0f)) return std::nullopt;
    // G2 / (|cos θi| cos θo) = 4 V with V = ggx_visibility's (sign-free in wi once mirrored).
    const float v4 = 4.0f * ggx_visibility(wo, mirror_z(wi), alpha);
    const float dv =
        ggx_d(*h, alpha) * v4 * cos_ih * cos_oh * side.eta_o * side.eta_o / (denom * denom);
    return MicrofacetTransmission{dv, cos_oh, cos_ih};
}

float ggx_transmission_pdf(const Vec3& wo, const Vec3& wi, float alpha, const Interface& side) {
    if (side.thin()) return wi.z < 0.0f ? ggx_reflection_pdf(wo, mirror_z(wi), alpha) : 0.0f;
    const std::optional<Vec3> h = transmission_half_vector(wo, wi, side);
    if (!h) return 0.0f;
    const float cos_oh = glm::dot(wo, *h);
    const float cos_ih = -glm::dot(wi, *h);
    const float denom = side.eta_o * cos_oh - side.eta_t * cos_ih;
    if (!(std::abs(denom) > 0.0f)) return 0.0f;
    // Walter et al. eq. 17: dω_h/dω_i = η_i² |wi·h| / (η_o wo·h + η_i wi·h)².
    return ggx_visible_normal_pdf(wo, *h, alpha) * side.eta_t * side.eta_t * cos_ih /
           (denom * denom);
}

}  // namespace mvpl::material
