#include "engine/material/node_eval.h"

namespace mvpl::material {

Vec3 normal_map(const Vec3& texel, float scale, const Frame& frame) {
    Vec3 n_ts = 2.0f * texel - Vec3(1.0f);
    n_ts.x *= scale;
    n_ts.y *= scale;
    const Vec3 n = frame.to_world(n_ts);
    const float len2 = glm::dot(n, n);
    // A zero texel (or a degenerate tangent frame) has no direction: keep the interpolated normal.
    if (!(len2 > 1e-12f) || !std::isfinite(len2)) return frame.n;
    const Vec3 result = n / std::sqrt(len2);
    return is_finite(result) ? result : frame.n;
}

Vec3 bump_map(float h, float h_u, float h_v, float du, float dv, float scale, const Frame& frame) {
    const float dh_du = du > 0.0f ? (h_u - h) / du : 0.0f;
    const float dh_dv = dv > 0.0f ? (h_v - h) / dv : 0.0f;
    const Vec3 n = frame.n - scale * (dh_du * frame.s + dh_dv * frame.t);
    const float len2 = glm::dot(n, n);
    if (!(len2 > 1e-12f) || !std::isfinite(len2)) return frame.n;
    return n / std::sqrt(len2);
}

ClosureParams lambertian(const Rgb& base_color) {
    ClosureParams c;
    c.base_color = base_color;
    c.metallic = 0.0f;
    c.specular = 0.0f;
    return clamp_to_valid_ranges(c);
}

ClosureParams ggx_conductor(const Rgb& f0, float roughness) {
    ClosureParams c;
    c.base_color = f0;
    c.metallic = 1.0f;
    c.roughness = roughness;
    return clamp_to_valid_ranges(c);
}

ClosureParams dielectric_diffuse(const Rgb& base_color, float roughness, float specular,
                                 const Rgb& specular_color, float ior) {
    return metal_rough(base_color, 0.0f, roughness, specular, specular_color, ior);
}

ClosureParams metal_rough(const Rgb& base_color, float metallic, float roughness, float specular,
                          const Rgb& specular_color, float ior) {
    ClosureParams c;
    c.base_color = base_color;
    c.metallic = metallic;
    c.roughness = roughness;
    c.specular = specular;
    c.specular_color = specular_color;
    c.ior = ior;
    return clamp_to_valid_ranges(c);
}

ClosureParams rough_dielectric(float roughness, float specular, const Rgb& specular_color,
                               float ior) {
    return metal_rough(Rgb(0.0f), 0.0f, roughness, specular, specular_color, ior);
}

ClosureType closure_type(const ClosureParams& params) {
    const ClosureParams c = clamp_to_valid_ranges(params);
    if (c.is_lambertian()) return ClosureType::Lambertian;
    if (c.metallic >= 1.0f) return ClosureType::Conductor;
    if (c.metallic <= 0.0f) return ClosureType::Dielectric;
    return ClosureType::MetalRough;
}

}  // namespace mvpl::material
