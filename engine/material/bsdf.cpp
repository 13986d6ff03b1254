#include "engine/material/bsdf.h"

#include "engine/core/sampling.h"
#include "engine/material/conductor.h"
#include "engine/material/lambertian.h"
#include "engine/material/microfacet.h"

namespace mvpl::material {

namespace {

// Bounds of the specular-lobe probability when both lobes are present: neither lobe is ever
// starved of samples, so a poor guess of its share costs at most a factor 10 in variance.
constexpr float kMinLobeProbability = 0.1f;
constexpr float kMaxLobeProbability = 0.9f;

}  // namespace

Bsdf::Bsdf(const ClosureParams& params) : m_params(params) {
    const ClosureParams p = clamp_to_valid_ranges(params);
    m_base_color = p.base_color;
    m_metallic = p.metallic;
    m_alpha = roughness_to_alpha(p.roughness);
    m_layer = dielectric_layer(p.specular_color, p.specular, p.ior);
    m_lambertian = p.is_lambertian();
    // The conductor always reflects (its F90 is 1); the dielectric layer only when F90 > 0.
    m_has_specular = !m_lambertian && (m_metallic > 0.0f || m_layer.f90 > 0.0f);
    // The base is visible unless the material is all metal, black, or fully covered by a layer
    // with F0 = F90 = 1.
    m_has_diffuse = m_metallic < 1.0f && max_component(m_base_color) > 0.0f &&
                    (m_lambertian || m_layer.f0_max < 1.0f);
}

Rgb Bsdf::eval(const Vec3& wo, const Vec3& wi) const {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return Rgb(0.0f);
    if (m_lambertian) return lambertian_eval(m_base_color, wo, wi);

    // f = (1 − m)·(w_d·base/π + F_d·DV) + m·F_c·DV, the microfacet term D·V shared by both layers.
    Rgb f(0.0f);
    if (m_has_diffuse) {
        f += (1.0f - m_metallic) * dielectric_diffuse_weight(m_layer, wo.z, wi.z) *
             lambertian_eval(m_base_color, wo, wi);
    }
    if (m_has_specular) {
        if (const std::optional<MicrofacetReflection> r = ggx_reflection(wo, wi, m_alpha)) {
            const Rgb fresnel = (1.0f - m_metallic) * dielectric_fresnel(m_layer, r->cos_oh) +
                                m_metallic * conductor_fresnel(m_base_color, r->cos_oh);
            f += fresnel * r->dv;
        }
    }
    return f;
}

float Bsdf::specular_probability(const Vec3& wo) const {
    if (!m_has_specular) return 0.0f;
    if (!m_has_diffuse) return 1.0f;
    // Expected share of each lobe in the reflected energy, estimated with the Fresnel of the
    // macro-surface at wo: the dielectric layer reflects ~F_d(cos θo), the base returns what the
    // layer transmits times its albedo, the conductor reflects ~F_c(cos θo).
    const float c = std::clamp(wo.z, 0.0f, 1.0f);
    const float e_specular = (1.0f - m_metallic) * luminance(dielectric_fresnel(m_layer, c)) +
                             m_metallic * luminance(conductor_fresnel(m_base_color, c));
    const float e_diffuse =
        (1.0f - m_metallic) * (1.0f - dielectric_max_fresnel(m_layer, c)) * luminance(m_base_color);
    const float total = e_specular + e_diffuse;
    const float p = total > 0.0f ? e_specular / total : 0.5f;
    return std::clamp(p, kMinLobeProbability, kMaxLobeProbability);
}

float Bsdf::pdf(const Vec3& wo, const Vec3& wi) const {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    if (m_lambertian) return lambertian_pdf(wo, wi);
    // The full mixture density, whichever lobe a sample came from (needed for MIS).
    const float p = specular_probability(wo);
    float density = 0.0f;
    if (p > 0.0f) density += p * ggx_reflection_pdf(wo, wi, m_alpha);
    if (p < 1.0f) density += (1.0f - p) * lambertian_pdf(wo, wi);
    return density;
}

std::optional<BsdfSample> Bsdf::sample(const Vec3& wo, const Vec2& u, float u_lobe) const {
    if (wo.z <= 0.0f) return std::nullopt;
    Vec3 wi;
    if (m_lambertian || u_lobe >= specular_probability(wo)) {
        wi = sample_cosine_hemisphere(u);
    } else {
        wi = reflect_about(wo, ggx_sample_visible_normal(wo, m_alpha, u));
    }
    // Reflections of visible normals can leave the hemisphere (the single-scattering energy
    // loss), and the cosine warp can return the horizon itself.
    if (wi.z <= 0.0f) return std::nullopt;
    const float density = pdf(wo, wi);
    if (!(density > 0.0f)) return std::nullopt;
    const Rgb weight = eval(wo, wi) * (wi.z / density);
    if (!is_finite(weight)) return std::nullopt;
    return BsdfSample{wi, weight, density};
}

}  // namespace mvpl::material
