#pragma once
// glTF 2.0 Appendix B `metal_brdf`: a GGX microfacet conductor whose Schlick Fresnel runs from
// F0 = base_color at normal incidence to 1 at grazing incidence:
//     f = (F0 + (1 − F0)(1 − |wo·h|)^5) · D(h) · G2(wo, wi) / (4 |cos θo| |cos θi|).
// Written once for C++ and GLSL in shaders/shared/closure_eval.h.
#include "engine/core/color.h"
#include "engine/material/fresnel.h"
#include "engine/material/microfacet.h"
#include "shaders/shared/closure_eval.h"

namespace mvpl::material {

using shared::math::conductor_fresnel;

// The full lobe for one pair of directions (0 unless both are above the surface).
Rgb conductor_eval(const Rgb& f0, float alpha, const Vec3& wo, const Vec3& wi);

}  // namespace mvpl::material
