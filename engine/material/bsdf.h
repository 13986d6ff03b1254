#pragma once
// The glTF metallic-roughness BRDF of a closure, in the local shading frame (z = shading normal).
// Directions point away from the surface. eval returns f (without the cosine); sample returns
// the direction, f·|cos θi|/pdf as weight, and the pdf in solid angle.
//
// f = (1 − metallic) · dielectric_brdf + metallic · metal_brdf (glTF 2.0 Appendix B), with the
// lobes of dielectric_diffuse.h and conductor.h. Reflection only: wo.z ≤ 0 or wi.z ≤ 0 gives
// eval 0, pdf 0 and no sample. Parameters are clamped to their glTF ranges on construction
// (clamp_to_valid_ranges in closure.h); GGX alpha = max(roughness², kMinAlpha) (microfacet.h).
#include <optional>

#include "engine/core/color.h"
#include "engine/core/math.h"
#include "engine/material/closure.h"
#include "engine/material/dielectric_diffuse.h"

namespace mvpl::material {

struct BsdfSample {
    Vec3 wi;
    Rgb weight;  // f · |cos θi| / pdf
    float pdf = 0.0f;
};

class Bsdf {
public:
    explicit Bsdf(const ClosureParams& params);

    Rgb eval(const Vec3& wo, const Vec3& wi) const;
    float pdf(const Vec3& wo, const Vec3& wi) const;
    // u_lobe picks the lobe; u samples the direction within it.
    std::optional<BsdfSample> sample(const Vec3& wo, const Vec2& u, float u_lobe) const;

    const ClosureParams& params() const { return m_params; }

    // Probability with which `sample` picks the specular lobe for this wo (the rest goes to the
    // cosine-sampled diffuse lobe); pdf() is the mixture p·pdf_spec + (1 − p)·pdf_diffuse.
    float specular_probability(const Vec3& wo) const;

private:
    ClosureParams m_params;  // as given
    // Derived from the clamped parameters in the constructor.
    Rgb m_base_color{0.0f};
    float m_metallic = 0.0f;
    float m_alpha = 1.0f;
    DielectricLayer m_layer;
    bool m_lambertian = true;
    bool m_has_specular = false;  // some lobe with a microfacet term is non-zero
    bool m_has_diffuse = true;    // the Lambertian base is non-zero somewhere
};

}  // namespace mvpl::material
