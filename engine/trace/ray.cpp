#include "engine/trace/ray.h"

#include <bit>
#include <cstdint>

namespace mvpl::trace {

Vec3 offset_ray_origin(const Vec3& p, const Vec3& ng, const Vec3& direction) {
    // Constants from Wächter and Binder (Ray Tracing Gems, ch. 6): below kOrigin the float grid is
    // too fine for integer ULP steps, so a small absolute offset takes over near the origin.
    constexpr float kOrigin = 1.0f / 32.0f;
    constexpr float kFloatScale = 1.0f / 65536.0f;
    constexpr float kIntScale = 256.0f;
    const Vec3 n = glm::dot(ng, direction) < 0.0f ? -ng : ng;
    Vec3 out;
    for (int i = 0; i < 3; ++i) {
        const int32_t of = static_cast<int32_t>(kIntScale * n[i]);
        const int32_t bits = std::bit_cast<int32_t>(p[i]);
        const float stepped = std::bit_cast<float>(bits + (p[i] < 0.0f ? -of : of));
        out[i] = std::abs(p[i]) < kOrigin ? p[i] + kFloatScale * n[i] : stepped;
    }
    return out;
}

Ray spawn_ray(const Vec3& p, const Vec3& ng, const Vec3& dir) {
    return Ray{offset_ray_origin(p, ng, dir), dir};
}

Ray spawn_ray_to(const Vec3& p, const Vec3& ng, const Vec3& target, const Vec3& target_ng) {
    const Vec3 origin = offset_ray_origin(p, ng, target - p);
    const bool on_surface = glm::dot(target_ng, target_ng) > 0.0f;
    const Vec3 end = on_surface ? offset_ray_origin(target, target_ng, origin - target) : target;
    // tmax is relative to the unnormalised direction: stop a hair before the end point whatever the
    // scene scale.
    return Ray{origin, end - origin, 1.0f - 1e-4f};
}

}  // namespace mvpl::trace
