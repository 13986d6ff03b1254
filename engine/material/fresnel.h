#pragma once
// Schlick's Fresnel approximation (Schlick 1994) as glTF 2.0 Appendix B uses it, and the
// reflectance at normal incidence of a dielectric interface (KHR_materials_ior): defined once, for
// C++ and GLSL, in shaders/shared/shading_math.h.
#include "engine/core/color.h"
#include "shaders/shared/shading_math.h"

namespace mvpl::material {

// (1 − |cos|)^5, glTF's `fresnel_w`.
using shared::math::schlick_weight;
// F = F0 + (F90 − F0)(1 − |cos|)^5, for Rgb and for one channel.
using shared::math::fresnel_schlick;
// ((ior − 1) / (ior + 1))², the normal-incidence reflectance against air (outside_ior = 1).
using shared::math::f0_from_ior;

}  // namespace mvpl::material
