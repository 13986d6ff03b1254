#pragma once
// The specular transmission of glTF's dielectric (KHR_materials_transmission with
// KHR_materials_ior and KHR_materials_volume): the same GGX distribution as the reflection lobe,
// weighted by what the layer does not reflect, (1 − F), and tinted by the base colour.
//
// Thin-walled (no volume, glTF's default): the transmitted ray keeps its direction. The lobe is
// the reflection lobe mirrored through the surface plane, f_t(wo, wi) = (1 − F(wo·h)) D(h) V with
// h = normalize(wo + (wi.x, wi.y, −wi.z)) (the KHR_materials_transmission spec's thin BTDF), so
// that F + (1 − F) = 1 per microfacet and its sampling is the reflection's, mirrored.
//
// Solid (KHR_materials_volume thickness > 0): refraction at a rough interface after Walter et al.
// 2007, eq. 21 (radiance; the adjoint for light paths is f·(η_i/η_o)², Veach 1997 §5.2):
//     f_t = |wi·h| |wo·h| η_o² (1 − F) D(h) G2(wo, wi) / (|cos θi| |cos θo| (η_o wo·h + η_i wi·h)²)
// with h = −normalize(η_o wo + η_i wi) turned to the normal's side, η_o the index on wo's side.
// The Fresnel term is Schlick's with the cosine on the optically thinner side, and 1 past the
// critical angle (total internal reflection).
//
// Directions are local (z = shading normal) and already turned so that wo.z > 0 (Bsdf does it).
#include <optional>

#include "engine/core/color.h"
#include "engine/core/math.h"
#include "engine/material/dielectric_diffuse.h"

namespace mvpl::material {

// The indices of refraction on the two sides of the interface: eta_o on wo's side, eta_t on the
// other. Thin-walled surfaces have 1 on both (no bending).
struct Interface {
    float eta_o = 1.0f;
    float eta_t = 1.0f;
    bool thin() const { return eta_o == eta_t; }
};

// The layer's Fresnel at a microfacet whose cosine with wo is cos_oh: Schlick's (as the
// reflection lobe) with the cosine on the thinner side, Rgb(1) under total internal reflection.
// From the denser side that cosine follows from Snell's law, unless the caller knows it
// (`cos_thin` ≥ 0: the transmitted direction's |wi·h|), which avoids the cancellation of
// 1 − η² sin² near the critical angle (and keeps eval reciprocal there).
Rgb interface_fresnel(const DielectricLayer& layer, float cos_oh, const Interface& side,
                      float cos_thin = -1.0f);

// wo refracted about the microfacet normal h (wo·h > 0); nullopt past the critical angle.
std::optional<Vec3> refract_about(const Vec3& wo, const Vec3& h, const Interface& side);

// The microfacet normal of a transmitted pair (wo.z > 0 > wi.z), on the normal's side, or nullopt
// when wo and wi cannot be joined by a refraction about a facet facing wo.
std::optional<Vec3> transmission_half_vector(const Vec3& wo, const Vec3& wi, const Interface& side);

// The BTDF's microfacet factor for a transmitted pair, without (1 − F) and the tint (so that Bsdf
// applies the Fresnel of its own layer), and the facet's cosine with wo.
struct MicrofacetTransmission {
    float dv = 0.0f;  // thin: D·V as ggx_reflection's; solid: the rest of eq. 21
    float cos_oh = 0.0f;
    float cos_ih = 0.0f;  // |wi·h|
};
std::optional<MicrofacetTransmission> ggx_transmission(const Vec3& wo, const Vec3& wi, float alpha,
                                                       const Interface& side);

// The solid-angle density of wi given the facet h ~ D_wo (visible normals) was transmitted
// (without the probability of choosing transmission over reflection at h).
float ggx_transmission_pdf(const Vec3& wo, const Vec3& wi, float alpha, const Interface& side);

// The mirror image of w through the surface plane.
inline Vec3 mirror_z(const Vec3& w) {
    return Vec3(w.x, w.y, -w.z);
}

}  // namespace mvpl::material
