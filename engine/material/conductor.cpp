#include "engine/material/conductor.h"

namespace mvpl::material {

Rgb conductor_eval(const Rgb& f0, float alpha, const Vec3& wo, const Vec3& wi) {
    const std::optional<MicrofacetReflection> r = ggx_reflection(wo, wi, alpha);
    if (!r) return Rgb(0.0f);
    return conductor_fresnel(f0, r->cos_oh) * r->dv;
}

}  // namespace mvpl::material
