#include "engine/material/conductor.h"

namespace mvpl::material {

Rgb conductor_eval(const Rgb& f0, float alpha, const Vec3& wo, const Vec3& wi) {
    return shared::math::conductor_reflection(f0, alpha, kLocalNormal, wo, wi);
}

}  // namespace mvpl::material
