#pragma once
// glTF 2.0 Appendix B `metal_brdf`: a GGX microfacet conductor whose Schlick Fresnel runs from
// F0 = base_color at normal incidence to 1 at grazing incidence:
//     f = (F0 + (1 − F0)(1 − |wo·h|)^5) · D(h) · G2(wo, wi) / (4 |cos θo| |cos θi|).
#include "engine/core/color.h"
#include "engine/material/fresnel.h"
#include "engine/material/microfacet.h"

namespace mvpl::material {

inline Rgb conductor_fresnel(const Rgb& f0, float cos_oh) {
    return fresnel_schlick(f0, Rgb(1.0f), cos_oh);
}

// The full lobe for one pair of directions (0 unless both are above the surface).
Rgb conductor_eval(const Rgb& f0, float alpha, const Vec3& wo, const Vec3& wi);

}  // namespace mvpl::material
