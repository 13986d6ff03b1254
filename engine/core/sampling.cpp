#include "engine/core/sampling.h"

namespace mvpl {

Vec2 sample_concentric_disk(const Vec2& u) {
    const Vec2 offset = 2.0f * u - Vec2(1.0f);
    if (offset.x == 0.0f && offset.y == 0.0f) return Vec2(0.0f);
    float r, theta;
    if (std::abs(offset.x) > std::abs(offset.y)) {
        r = offset.x;
        theta = (kPi / 4.0f) * (offset.y / offset.x);
    } else {
        r = offset.y;
        theta = kPi / 2.0f - (kPi / 4.0f) * (offset.x / offset.y);
    }
    return r * Vec2(std::cos(theta), std::sin(theta));
}

Vec3 sample_cosine_hemisphere(const Vec2& u) {
    const Vec2 d = sample_concentric_disk(u);
    const float z = safe_sqrt(1.0f - d.x * d.x - d.y * d.y);
    return Vec3(d.x, d.y, z);
}

Vec3 sample_uniform_sphere(const Vec2& u) {
    const float z = 1.0f - 2.0f * u.x;
    const float r = safe_sqrt(1.0f - z * z);
    const float phi = 2.0f * kPi * u.y;
    return Vec3(r * std::cos(phi), r * std::sin(phi), z);
}

Vec3 sample_uniform_cone(const Vec2& u, float cos_max) {
    const float cos_theta = (1.0f - u.x) + u.x * cos_max;
    const float sin_theta = safe_sqrt(1.0f - cos_theta * cos_theta);
    const float phi = 2.0f * kPi * u.y;
    return Vec3(sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta);
}

Vec2 sample_uniform_triangle(const Vec2& u) {
    float b0, b1;
    if (u.x < u.y) {
        b0 = u.x / 2.0f;
        b1 = u.y - b0;
    } else {
        b1 = u.y / 2.0f;
        b0 = u.x - b1;
    }
    return Vec2(b1, 1.0f - b0 - b1);
}

}  // namespace mvpl
