#include "engine/scene/environment.h"

#include <algorithm>
#include <cmath>

namespace mvpl::scene {

Vec2 Environment::direction_to_uv(const Vec3& w) const {
    // Undo the rotation: the map is turned by `rotation` about +Y.
    const float c = std::cos(rotation), s = std::sin(rotation);
    const Vec3 d(c * w.x - s * w.z, w.y, s * w.x + c * w.z);
    const float phi = std::atan2(d.z, d.x);                       // (−π, π], 0 towards +X
    const float theta = std::acos(std::clamp(d.y, -1.0f, 1.0f));  // 0 at +Y
    const float u = 0.5f + phi / (2.0f * kPi);
    const float v = theta / kPi;
    constexpr float kBelowOne = 0x1.fffffep-1f;
    return Vec2(std::clamp(u - std::floor(u), 0.0f, kBelowOne), std::clamp(v, 0.0f, kBelowOne));
}

Vec3 Environment::uv_to_direction(const Vec2& uv, float* sin_theta) const {
    const float phi = (uv.x - 0.5f) * 2.0f * kPi;
    const float theta = uv.y * kPi;
    const float st = std::sin(theta);
    if (sin_theta) *sin_theta = st;
    const Vec3 d(st * std::cos(phi), std::cos(theta), st * std::sin(phi));
    const float c = std::cos(rotation), s = std::sin(rotation);
    return Vec3(c * d.x + s * d.z, d.y, -s * d.x + c * d.z);
}

Rgb Environment::lookup(const Vec3& w) const {
    if (!has_map()) return radiance;
    const Vec2 uv = direction_to_uv(w);
    const int x = std::min(int(uv.x * float(map->width)), map->width - 1);
    const int y = std::min(int(uv.y * float(map->height)), map->height - 1);
    return map->at(x, y) * radiance;
}

}  // namespace mvpl::scene
