#pragma once
// Lambertian reflection f = ρ / π, sampled with a cosine-weighted hemisphere (pdf = cos θi / π), so
// that the sample weight f cos θi / pdf is ρ exactly. The fast path of closures with no specular
// layer (ClosureParams::is_lambertian) and the diffuse lobe of the dielectric-over-diffuse model.
#include "engine/core/color.h"
#include "engine/core/sampling.h"
#include "shaders/shared/lambertian.h"

namespace mvpl::material {

using shared::math::kLocalNormal;

// f itself, shaders/shared/lambertian.h's (which the GPU evaluates too).
inline Rgb lambertian_eval(const Rgb& albedo, const Vec3& wo, const Vec3& wi) {
    return shared::math::lambertian_reflection(albedo, kLocalNormal, wo, wi);
}

inline float lambertian_pdf(const Vec3& wo, const Vec3& wi) {
    return wo.z > 0.0f ? cosine_hemisphere_pdf(wi.z) : 0.0f;
}

}  // namespace mvpl::material
