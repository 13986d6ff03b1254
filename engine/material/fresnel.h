#pragma once
// Schlick's Fresnel approximation (Schlick 1994) as glTF 2.0 Appendix B uses it, and the
// reflectance at normal incidence of a dielectric interface (KHR_materials_ior).
#include "engine/core/color.h"

namespace mvpl::material {

// (1 − |cos|)^5, glTF's `fresnel_w`.
inline float schlick_weight(float cos_theta) {
    const float m = std::clamp(1.0f - std::abs(cos_theta), 0.0f, 1.0f);
    const float m2 = m * m;
    return m2 * m2 * m;
}

// F = F0 + (F90 − F0)(1 − |cos|)^5.
inline Rgb fresnel_schlick(const Rgb& f0, const Rgb& f90, float cos_theta) {
    return f0 + (f90 - f0) * schlick_weight(cos_theta);
}
inline float fresnel_schlick(float f0, float f90, float cos_theta) {
    return f0 + (f90 - f0) * schlick_weight(cos_theta);
}

// ((ior − 1) / (ior + 1))², the normal-incidence reflectance against air (outside_ior = 1).
// KHR_materials_specular uses ior = 0 as "F0 = 1" (its specular-glossiness conversion); negative
// values are outside the extension's schema and are treated as ior = 0 rather than dividing by 0.
inline float f0_from_ior(float ior) {
    const float n = std::max(ior, 0.0f);
    return sqr((n - 1.0f) / (n + 1.0f));
}

}  // namespace mvpl::material
