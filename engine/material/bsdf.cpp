#include "engine/material/bsdf.h"

#include "engine/core/sampling.h"
#include "engine/material/conductor.h"
#include "engine/material/lambertian.h"
#include "engine/material/microfacet.h"
#include "engine/material/transmission.h"

namespace mvpl::material {

namespace {

// Bounds of the specular-lobe probability when both lobes are present: neither lobe is ever
// starved of samples, so a poor guess of its share costs at most a factor 10 in variance.
constexpr float kMinLobeProbability = 0.1f;
constexpr float kMaxLobeProbability = 0.9f;

}  // namespace

// wo turned above the surface (`flip` = −1 mirrors it and every wi through the plane), and the
// indices of refraction on its side and the other.
struct Bsdf::Oriented {
    Vec3 wo;
    float flip = 1.0f;
    Interface side;
    // Outside a solid (or thin-walled): the dielectric layer's Fresnel is Schlick's of the
    // cosine with wo, as the GPU shades it.
    bool outside() const { return side.eta_o <= side.eta_t; }
};

Bsdf::Bsdf(const ClosureParams& params) : m_params(params) {
    const ClosureParams p = clamp_to_valid_ranges(params);
    m_layer = dielectric_layer(p.specular_color, p.specular, p.ior);
    m_transmits = p.transmits();
    m_lobes =
        shared::math::reflection_lobes(p.base_color, p.metallic, roughness_to_alpha(p.roughness),
                                       m_layer.f0, m_layer.f90, m_transmits);
    m_transmission = m_transmits ? (1.0f - p.metallic) * p.transmission : Rgb(0.0f);
    // ior 0 (F0 = 1, allowed by KHR_materials_ior) has no refracted direction: thin.
    m_thin = p.thin_walled || !(p.ior > 0.0f);
    m_ior = p.ior;
}

std::optional<Bsdf::Oriented> Bsdf::orient(const Vec3& wo) const {
    Oriented o;
    if (wo.z > 0.0f) {
        o.wo = wo;
        if (m_transmits && !m_thin) o.side = Interface{1.0f, m_ior};
        return o;
    }
    if (!m_transmits || !(wo.z < 0.0f)) return std::nullopt;
    o.wo = mirror_z(wo);
    o.flip = -1.0f;
    if (!m_thin) o.side = Interface{m_ior, 1.0f};  // inside the solid
    return o;
}

float Bsdf::macro_fresnel(float cos_theta, const Oriented& o) const {
    // dielectric_max_fresnel outside (dielectric_diffuse.h's w_d); inside a solid, total internal
    // reflection keeps the base's light in: the same Schlick of max(F0) with the interface's
    // cosine, so that the diffuse base never adds to what the reflection already returns.
    if (o.outside()) return dielectric_max_fresnel(m_layer, cos_theta);
    return max_component(interface_fresnel(m_layer, cos_theta, o.side));
}

Rgb Bsdf::reflection_fresnel(float cos_oh, const Oriented& o) const {
    return shared::math::metal_rough_fresnel(m_lobes, interface_fresnel(m_layer, cos_oh, o.side),
                                             cos_oh);
}

float Bsdf::reflect_probability(float cos_oh, const Oriented& o) const {
    if (!m_transmits) return 1.0f;
    // Each in proportion to its weight at this facet: reflection F, transmission T·(1 − F).
    const Rgb f = interface_fresnel(m_layer, cos_oh, o.side);
    const float e_reflect = luminance(reflection_fresnel(cos_oh, o));
    const float e_transmit = luminance(m_transmission * (Rgb(1.0f) - f));
    const float total = e_reflect + e_transmit;
    return total > 0.0f ? e_reflect / total : 1.0f;
}

Rgb Bsdf::eval(const Vec3& wo, const Vec3& wi, Transport mode) const {
    const std::optional<Oriented> o = orient(wo);
    if (!o) return Rgb(0.0f);
    return eval_oriented(*o, o->flip > 0.0f ? wi : mirror_z(wi), mode);
}

Rgb Bsdf::eval_oriented(const Oriented& o, const Vec3& wi, Transport mode) const {
    const Vec3& wo = o.wo;
    if (wi.z > 0.0f) {
        // Outside (or thin): what the GPU shades, shaders/shared/closure_eval.h.
        if (o.outside()) return shared::math::metal_rough_reflection(m_lobes, kLocalNormal, wo, wi);
        // Inside a solid: the same mix with the interface's Fresnel.
        Rgb f = eval_diffuse_oriented(o, wi);
        if (const std::optional<MicrofacetReflection> r = ggx_reflection(wo, wi, m_lobes.alpha))
            f += reflection_fresnel(r->cos_oh, o) * r->dv;
        return f;
    }
    if (!m_transmits || !(wi.z < 0.0f)) return Rgb(0.0f);
    const std::optional<MicrofacetTransmission> t = ggx_transmission(wo, wi, m_lobes.alpha, o.side);
    if (!t) return Rgb(0.0f);
    const Rgb fresnel = interface_fresnel(m_layer, t->cos_oh, o.side, t->cos_ih);
    Rgb f = m_transmission * (Rgb(1.0f) - fresnel) * t->dv;
    // Walter et al.'s η_o² is radiance's; the adjoint has η_i² (Veach 1997, eq. 5.19).
    if (mode == Transport::Importance && !o.side.thin()) f *= sqr(o.side.eta_t / o.side.eta_o);
    return f;
}

Rgb Bsdf::eval_diffuse(const Vec3& wo, const Vec3& wi) const {
    const std::optional<Oriented> o = orient(wo);
    if (!o) return Rgb(0.0f);
    return eval_diffuse_oriented(*o, o->flip > 0.0f ? wi : mirror_z(wi));
}

Rgb Bsdf::eval_diffuse_oriented(const Oriented& o, const Vec3& wi) const {
    const Vec3& wo = o.wo;
    if (o.outside()) return shared::math::metal_rough_diffuse(m_lobes, kLocalNormal, wo, wi);
    // Inside a solid (never Lambertian: it transmits).
    if (!(wi.z > 0.0f) || !m_lobes.has_diffuse) return Rgb(0.0f);
    return shared::math::metal_rough_diffuse_lobe(m_lobes, macro_fresnel(wo.z, o),
                                                  macro_fresnel(wi.z, o));
}

float Bsdf::pdf_diffuse(const Vec3& wo, const Vec3& wi) const {
    if (!m_lobes.lambertian && !m_lobes.has_diffuse) return 0.0f;
    const std::optional<Oriented> o = orient(wo);
    if (!o) return 0.0f;
    const Vec3 w = o->flip > 0.0f ? wi : mirror_z(wi);
    return w.z > 0.0f ? lambertian_pdf(o->wo, w) : 0.0f;
}

std::optional<BsdfSample> Bsdf::sample_diffuse(const Vec3& wo, const Vec2& u,
                                               float /*u_lobe*/) const {
    if (!m_lobes.lambertian && !m_lobes.has_diffuse) return std::nullopt;
    const std::optional<Oriented> o = orient(wo);
    if (!o) return std::nullopt;
    // As sample() does when it picks the diffuse lobe.
    const Vec3 wi = sample_cosine_hemisphere(u);
    if (!(wi.z > 0.0f)) return std::nullopt;
    const float density = lambertian_pdf(o->wo, wi);
    if (!(density > 0.0f)) return std::nullopt;
    const Rgb weight = eval_diffuse_oriented(*o, wi) * (std::abs(wi.z) / density);
    if (!is_finite(weight)) return std::nullopt;
    return BsdfSample{o->flip > 0.0f ? wi : mirror_z(wi), weight, density};
}

float Bsdf::specular_probability(const Vec3& wo) const {
    const std::optional<Oriented> o = orient(wo);
    return o ? specular_probability(*o) : 0.0f;
}

float Bsdf::specular_probability(const Oriented& o) const {
    if (!m_lobes.has_specular) return 0.0f;
    if (!m_lobes.has_diffuse) return 1.0f;
    // Expected share of each lobe in the scattered energy, estimated with the Fresnel of the
    // macro-surface at wo: the dielectric layer reflects ~F_d(cos θo) and transmits the rest of
    // the transmission share, the base returns what the layer transmits times its albedo, the
    // conductor reflects ~F_c(cos θo).
    const float c = std::clamp(o.wo.z, 0.0f, 1.0f);
    const Rgb f = interface_fresnel(m_layer, c, o.side);
    const float e_specular =
        (1.0f - m_lobes.metallic) * luminance(f) +
        m_lobes.metallic * luminance(conductor_fresnel(m_lobes.base_color, c)) +
        luminance(m_transmission) * (1.0f - max_component(f));
    const float e_diffuse =
        (1.0f - m_lobes.metallic) * (1.0f - macro_fresnel(c, o)) * luminance(m_lobes.base_color);
    const float total = e_specular + e_diffuse;
    const float p = total > 0.0f ? e_specular / total : 0.5f;
    return std::clamp(p, kMinLobeProbability, kMaxLobeProbability);
}

float Bsdf::transmission_share(const Vec3& wo) const {
    if (!m_transmits) return 0.0f;
    const std::optional<Oriented> o = orient(wo);
    if (!o) return 0.0f;
    const float c = std::clamp(o->wo.z, 0.0f, 1.0f);
    const Rgb f = interface_fresnel(m_layer, c, o->side);
    const float e_transmit = luminance(m_transmission) * (1.0f - max_component(f));
    const float e_reflect = (1.0f - m_lobes.metallic) * luminance(f) +
                            m_lobes.metallic * luminance(conductor_fresnel(m_lobes.base_color, c));
    const float e_diffuse =
        (1.0f - m_lobes.metallic) * (1.0f - macro_fresnel(c, *o)) * luminance(m_lobes.base_color);
    const float total = e_transmit + e_reflect + e_diffuse;
    return total > 0.0f ? e_transmit / total : 0.0f;
}

float Bsdf::pdf(const Vec3& wo, const Vec3& wi) const {
    const std::optional<Oriented> o = orient(wo);
    if (!o) return 0.0f;
    return pdf_oriented(*o, o->flip > 0.0f ? wi : mirror_z(wi));
}

float Bsdf::pdf_oriented(const Oriented& o, const Vec3& wi) const {
    const Vec3& wo = o.wo;
    if (m_lobes.lambertian) return wi.z > 0.0f ? lambertian_pdf(wo, wi) : 0.0f;
    // The full mixture density, whichever lobe a sample came from (needed for MIS).
    const float p = specular_probability(o);
    if (wi.z > 0.0f) {
        float density = 0.0f;
        if (p > 0.0f) {
            if (const std::optional<Vec3> h = reflection_half_vector(wo, wi)) {
                density += p * ggx_reflection_pdf(wo, wi, m_lobes.alpha) *
                           reflect_probability(glm::dot(wo, *h), o);
            }
        }
        if (p < 1.0f) density += (1.0f - p) * lambertian_pdf(wo, wi);
        return density;
    }
    if (!m_transmits || !(wi.z < 0.0f) || !(p > 0.0f)) return 0.0f;
    const std::optional<Vec3> h = transmission_half_vector(wo, wi, o.side);
    if (!h) return 0.0f;
    return p * ggx_transmission_pdf(wo, wi, m_lobes.alpha, o.side) *
           (1.0f - reflect_probability(glm::dot(wo, *h), o));
}

std::optional<BsdfSample> Bsdf::sample(const Vec3& wo, const Vec2& u, float u_lobe,
                                       Transport mode) const {
    const std::optional<Oriented> o = orient(wo);
    if (!o) return std::nullopt;
    const float p = m_lobes.lambertian ? 0.0f : specular_probability(*o);
    Vec3 wi;
    bool transmitted = false;
    if (u_lobe >= p) {
        wi = sample_cosine_hemisphere(u);
    } else {
        const Vec3 h = ggx_sample_visible_normal(o->wo, m_lobes.alpha, u);
        // u_lobe / p is uniform in [0, 1) given that this lobe was picked: it picks reflection or
        // transmission at the facet.
        if (u_lobe / p < reflect_probability(glm::dot(o->wo, h), *o)) {
            wi = reflect_about(o->wo, h);
        } else if (o->side.thin()) {
            wi = mirror_z(reflect_about(o->wo, h));
            transmitted = true;
        } else {
            const std::optional<Vec3> r = refract_about(o->wo, h, o->side);
            if (!r) return std::nullopt;
            wi = *r;
            transmitted = true;
        }
    }
    // Reflections of visible normals can leave the hemisphere (the single-scattering energy
    // loss), and the cosine warp can return the horizon itself.
    if (transmitted ? !(wi.z < 0.0f) : !(wi.z > 0.0f)) return std::nullopt;
    const float density = pdf_oriented(*o, wi);
    if (!(density > 0.0f)) return std::nullopt;
    const Rgb weight = eval_oriented(*o, wi, mode) * (std::abs(wi.z) / density);
    if (!is_finite(weight)) return std::nullopt;
    return BsdfSample{o->flip > 0.0f ? wi : mirror_z(wi), weight, density};
}

}  // namespace mvpl::material
