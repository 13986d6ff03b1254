#pragma once
// The glTF metallic-roughness BSDF of a closure, in the local shading frame (z = shading normal).
// Directions point away from the surface. eval returns f (without the cosine); sample returns
// the direction, f·|cos θi|/pdf as weight, and the pdf in solid angle.
//
// f = (1 − metallic) · dielectric_bsdf + metallic · metal_brdf (glTF 2.0 Appendix B), with the
// lobes of dielectric_diffuse.h and conductor.h, and KHR_materials_transmission's specular BTDF
// (transmission.h) in the dielectric: ClosureParams::transmission = t · base colour replaces the
// share t of the diffuse base (whose colour the closure already holds scaled by 1 − t).
//
// Sides. An opaque closure reflects only: wo.z ≤ 0 or wi.z ≤ 0 gives eval 0, pdf 0 and no
// sample. A transmissive one scatters into both hemispheres and is seen from both: a thin-walled
// surface is the same from below (both directions mirrored through the plane); a solid's frame
// faces out of the solid (make_shading_point does not flip it), so wo.z < 0 is inside, where the
// interface refracts with 1/ior and may reflect totally.
//
// Smooth transmission is the narrowest GGX lobe the reflection already uses (α ≥ kMinAlpha =
// 10⁻⁴, microfacet.h), not a delta: eval/pdf/sample stay one consistent code path (MIS and the
// chains' weights need no special case), and the 10⁻⁴ rad lobe is three orders of magnitude wider
// than a float half vector's rounding, so eval reproduces the density sample drew from.
//
// Parameters are clamped to their glTF ranges on construction (clamp_to_valid_ranges in
// closure.h); GGX alpha = max(roughness², kMinAlpha) (microfacet.h).
#include <optional>

#include "engine/core/color.h"
#include "engine/core/math.h"
#include "engine/material/closure.h"
#include "engine/material/dielectric_diffuse.h"
#include "shaders/shared/closure_eval.h"

namespace mvpl::material {

struct BsdfSample {
    Vec3 wi;
    Rgb weight;  // f · |cos θi| / pdf
    float pdf = 0.0f;
};

// What a sampled or evaluated pair of directions transports (Veach 1997, §5.2): camera paths
// carry radiance, light paths importance; refraction scales the two differently by (η_i/η_o)².
enum class Transport { Radiance, Importance };

class Bsdf {
public:
    explicit Bsdf(const ClosureParams& params);

    Rgb eval(const Vec3& wo, const Vec3& wi, Transport mode = Transport::Radiance) const;
    // The diffuse lobe of eval alone: the Lambertian base under its Fresnel weight,
    // (1 − metallic)·w_d·base/π (all of f for a Lambertian closure); eval minus this is the
    // microfacet reflection and transmission. It does not depend on the roughness, so a widened
    // closure (light/virtual_sphere.h) has the same diffuse lobe. Clamping lobe by lobe
    // (light/vpl_contribution.h) and its compensation (integrator/clamp_compensation.h) use it.
    Rgb eval_diffuse(const Vec3& wo, const Vec3& wi) const;
    // The diffuse lobe alone as a BSDF of its own, sampled with its cosine density: pdf_diffuse
    // is that density (0 where the lobe is absent), sample_diffuse's weight is
    // eval_diffuse·|cos θi|/pdf_diffuse. u_lobe is ignored (as a Lambertian sample() ignores
    // it): on a Lambertian closure both are pdf and sample exactly, so that lobe-restricted
    // estimators reproduce the full ones bit for bit on diffuse scenes.
    float pdf_diffuse(const Vec3& wo, const Vec3& wi) const;
    std::optional<BsdfSample> sample_diffuse(const Vec3& wo, const Vec2& u,
                                             float u_lobe = 0.0f) const;
    // Whether some lobe besides the diffuse one can be non-zero.
    bool has_glossy() const { return m_lobes.has_specular; }
    float pdf(const Vec3& wo, const Vec3& wi) const;
    // u_lobe picks the lobe (and reflection or transmission at the sampled facet); u samples the
    // direction within it.
    std::optional<BsdfSample> sample(const Vec3& wo, const Vec2& u, float u_lobe,
                                     Transport mode = Transport::Radiance) const;

    const ClosureParams& params() const { return m_params; }

    // Probability with which `sample` picks the microfacet lobe (reflection or transmission) for
    // this wo (the rest goes to the cosine-sampled diffuse lobe); pdf() is the mixture
    // p·pdf_microfacet + (1 − p)·pdf_diffuse.
    float specular_probability(const Vec3& wo) const;
    // The expected share of the transmission lobe in what the surface scatters from wo, from the
    // macro-surface's Fresnel (0 for opaque closures).
    float transmission_share(const Vec3& wo) const;
    // The surface transmits (ClosureParams::transmits): seen and scattered from both sides.
    bool transmits() const { return m_transmits; }
    bool thin_walled() const { return m_thin; }

private:
    struct Oriented;  // wo turned above the surface, with the interface's indices
    std::optional<Oriented> orient(const Vec3& wo) const;
    float specular_probability(const Oriented& o) const;
    // Probability of reflecting (rather than transmitting) at facet cosine cos_oh.
    float reflect_probability(float cos_oh, const Oriented& o) const;
    Rgb reflection_fresnel(float cos_oh, const Oriented& o) const;
    // max_value(F) of the macro-surface at cos θ, what weights the diffuse base.
    float macro_fresnel(float cos_theta, const Oriented& o) const;
    Rgb eval_oriented(const Oriented& o, const Vec3& wi, Transport mode) const;
    Rgb eval_diffuse_oriented(const Oriented& o, const Vec3& wi) const;
    float pdf_oriented(const Oriented& o, const Vec3& wi) const;

    ClosureParams m_params;  // as given
    // Derived from the clamped parameters in the constructor: the reflection lobes that the GPU
    // shades too (shaders/shared/closure_eval.h), and what only the CPU does.
    shared::math::ReflectionLobes m_lobes;
    Rgb m_transmission{0.0f};  // (1 − metallic) · t · base colour
    float m_ior = 1.5f;
    DielectricLayer m_layer;
    bool m_transmits = false;
    bool m_thin = true;
};

}  // namespace mvpl::material
