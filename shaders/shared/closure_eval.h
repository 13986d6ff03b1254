// The opaque closures' reflection f(wo, wi), without the cosine, written once for C++ and GLSL:
// glTF 2.0 Appendix B's mix f = (1 − metallic)·dielectric_brdf + metallic·metal_brdf, the
// conductor's Schlick Fresnel running from the base colour to 1, the dielectric layer of
// KHR_materials_specular and KHR_materials_ior over a Lambertian base weighted by the
// macro-surface's Fresnel (engine/material/dielectric_diffuse.h says why that weight), the
// microfacet terms of shading_math.h. engine/material/bsdf.h derives ReflectionLobes once per
// closure and adds around these functions what the GPU does not shade (the transmission lobe, the
// inside of a solid); glsl_library.cpp derives them per call from a Closure ("metal_rough_eval"
// and its kin). Directions about n as in shading_math.h, whose common subset this file keeps.
#ifndef MVPL_SHADERS_SHARED_CLOSURE_EVAL_H
#define MVPL_SHADERS_SHARED_CLOSURE_EVAL_H

#ifdef __cplusplus
#include "engine/core/color.h"
#include "shaders/shared/lambertian.h"
#include "shaders/shared/shading_math.h"

namespace mvpl::shared::math {
using ::mvpl::max_component;
#endif

// A closure's reflection lobes, from its parameters clamped to the glTF ranges (closure.h).
struct ReflectionLobes {
    vec3 base_color;
    float metallic;
    vec3 f0;  // the dielectric layer's, at normal incidence (dielectric_f0)
    float f90;
    float f0_max;  // max_component(f0), what weights the diffuse base (F0 ≤ F90 makes it monotone)
    float alpha;   // GGX α (roughness_to_alpha)
    bool lambertian;    // metallic and specular 0, no transmission: f = base/π
    bool has_specular;  // some lobe with a microfacet term can be non-zero
    bool has_diffuse;   // the Lambertian base is non-zero somewhere
};

// KHR_materials_specular: F0 = min(((ior − 1)/(ior + 1))² · specular_color, 1) · specular, the
// clamp before the multiplication so that F0 ≤ F90 = specular.
MVPL_INLINE vec3 dielectric_f0(vec3 specular_color, float specular, float ior) {
    return min(f0_from_ior(ior) * specular_color, vec3(1.0f)) * specular;
}

// `transmits`: Bsdf's transmission lobe (the CPU's only) is present, a microfacet lobe that makes
// the closure more than Lambertian.
MVPL_INLINE ReflectionLobes reflection_lobes(vec3 base_color, float metallic, float alpha, vec3 f0,
                                             float f90, bool transmits) {
    ReflectionLobes l;
    l.base_color = base_color;
    l.metallic = metallic;
    l.f0 = f0;
    l.f90 = f90;
    l.f0_max = max_component(f0);
    l.alpha = alpha;
    l.lambertian = metallic <= 0.0f && f90 <= 0.0f && !transmits;
    // The conductor always reflects (its F90 is 1), the dielectric layer when F90 > 0.
    l.has_specular = !l.lambertian && (metallic > 0.0f || f90 > 0.0f || transmits);
    // The base is visible unless all metal, black, or under a layer with F0 = F90 = 1.
    l.has_diffuse =
        metallic < 1.0f && max_component(base_color) > 0.0f && (l.lambertian || l.f0_max < 1.0f);
    return l;
}

// metal_brdf's Fresnel: F0 = the base colour, F90 = 1.
MVPL_INLINE vec3 conductor_fresnel(vec3 f0, float cos_oh) {
    return fresnel_schlick(f0, vec3(1.0f), cos_oh);
}

// The conductor alone (metallic 1): F·D·V.
MVPL_INLINE vec3 conductor_reflection(vec3 f0, float alpha, MVPL_NORMAL n, vec3 wo, vec3 wi) {
    if (!(dot(n, wo) > 0.0f) || !(dot(n, wi) > 0.0f)) return vec3(0.0f);
    const vec3 r = ggx_reflection(n, wo, wi, alpha);
    return r.z > 0.0f ? conductor_fresnel(f0, r.y) * r.x : vec3(0.0f);
}

// The Fresnel of the mix's microfacet reflection at a facet of cosine cos_oh, given the dielectric
// layer's (Schlick's outside; Bsdf's interface_fresnel inside a solid).
MVPL_INLINE vec3 metal_rough_fresnel(ReflectionLobes l, vec3 dielectric_fresnel, float cos_oh) {
    return (1.0f - l.metallic) * dielectric_fresnel +
           l.metallic * conductor_fresnel(l.base_color, cos_oh);
}

// The diffuse base (1 − metallic)·w_d·base/π, w_d = (1 − F(cos θo))(1 − F(cos θi)) from the
// macro-surface's max_value(F) towards wo and wi.
MVPL_INLINE vec3 metal_rough_diffuse_lobe(ReflectionLobes l, float fresnel_o, float fresnel_i) {
    const float w_d = (1.0f - fresnel_o) * (1.0f - fresnel_i);
    return (1.0f - l.metallic) * w_d * lambertian_f(l.base_color);
}

// The diffuse lobe for the cosines co = n·wo > 0 and ci = n·wi > 0 (each computed once).
MVPL_INLINE vec3 metal_rough_diffuse_of(ReflectionLobes l, float co, float ci) {
    if (l.lambertian) return lambertian_f(l.base_color);
    if (!l.has_diffuse) return vec3(0.0f);
    return metal_rough_diffuse_lobe(l, fresnel_schlick(l.f0_max, l.f90, co),
                                    fresnel_schlick(l.f0_max, l.f90, ci));
}

// The diffuse lobe of metal_rough_reflection alone (Bsdf::eval_diffuse): all of a Lambertian
// closure's f, none of a conductor's; independent of the roughness.
MVPL_INLINE vec3 metal_rough_diffuse(ReflectionLobes l, MVPL_NORMAL n, vec3 wo, vec3 wi) {
    const float co = dot(n, wo);
    const float ci = dot(n, wi);
    if (!(co > 0.0f) || !(ci > 0.0f)) return vec3(0.0f);
    return metal_rough_diffuse_of(l, co, ci);
}

// f = (1 − m)·(w_d·base/π + F_d·D·V) + m·F_c·D·V, the microfacet term D·V shared by both layers;
// a Lambertian closure (no microfacet lobe) is its diffuse lobe alone.
MVPL_INLINE vec3 metal_rough_reflection(ReflectionLobes l, MVPL_NORMAL n, vec3 wo, vec3 wi) {
    const float co = dot(n, wo);
    const float ci = dot(n, wi);
    if (!(co > 0.0f) || !(ci > 0.0f)) return vec3(0.0f);
    vec3 f = metal_rough_diffuse_of(l, co, ci);
    if (l.has_specular) {
        const vec3 r = ggx_reflection(n, wo, wi, l.alpha);
        if (r.z > 0.0f)
            f += metal_rough_fresnel(l, fresnel_schlick(l.f0, vec3(l.f90), r.y), r.y) * r.x;
    }
    return f;
}

#ifdef __cplusplus
}  // namespace mvpl::shared::math
#endif

#endif
