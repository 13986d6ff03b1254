#pragma once
#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>

#include "engine/core/math.h"

namespace mvpl::trace {

struct Ray {
    Vec3 origin;
    Vec3 direction;  // need not be unit; t is measured in its units
    float tmax = std::numeric_limits<float>::infinity();
};

// Inline: the reduced matrix (manylights/) builds a shadow ray an entry, R · N a pool.
//
// Moves a surface point off its triangle along the geometric normal, to the side `direction`
// leaves from, by a few ULPs of its coordinates (Wächter and Binder, "A Fast and Robust Method for
// Avoiding Self-Intersection", Ray Tracing Gems ch. 6). Near the origin, where ULP steps become
// too fine, their constant offset takes over; `coordinate_scale` (Accel::coordinate_scale: the
// scene's largest |coordinate|) shrinks that constant and the region where it applies with a
// scene smaller than a metre, so that a 20 µm box is offset as a 2 m one is (issue 32: the
// constant 1.5·10⁻⁵ was the whole box). Larger scenes keep the constant: a point near the origin
// may lie on a triangle of any size there.
inline Vec3 offset_ray_origin(const Vec3& p, const Vec3& ng, const Vec3& direction,
                              float coordinate_scale) {
    // Constants from Wächter and Binder (Ray Tracing Gems, ch. 6), for a scene of about a metre:
    // below `origin` the float grid is too fine for integer ULP steps, so a small absolute offset
    // takes over near the origin. Both shrink with a smaller scene (above).
    const float scale = std::clamp(coordinate_scale, 1e-30f, 1.0f);
    const float origin = scale / 32.0f;
    const float float_scale = scale / 65536.0f;
    constexpr float kIntScale = 256.0f;
    const Vec3 n = glm::dot(ng, direction) < 0.0f ? -ng : ng;
    Vec3 out;
    for (int i = 0; i < 3; ++i) {
        const int32_t of = static_cast<int32_t>(kIntScale * n[i]);
        const int32_t bits = std::bit_cast<int32_t>(p[i]);
        const float stepped = std::bit_cast<float>(bits + (p[i] < 0.0f ? -of : of));
        out[i] = std::abs(p[i]) < origin ? p[i] + float_scale * n[i] : stepped;
    }
    return out;
}

// A ray leaving surface point p (geometric normal ng) in direction dir.
inline Ray spawn_ray(const Vec3& p, const Vec3& ng, const Vec3& dir, float coordinate_scale) {
    return Ray{offset_ray_origin(p, ng, dir, coordinate_scale), dir};
}
// A shadow ray from surface point p towards `target`, stopping just short of it. Pass the
// target's geometric normal when it lies on a surface (zero vector for a point light).
inline Ray spawn_ray_to(const Vec3& p, const Vec3& ng, const Vec3& target, const Vec3& target_ng,
                        float coordinate_scale) {
    const Vec3 origin = offset_ray_origin(p, ng, target - p, coordinate_scale);
    const bool on_surface = glm::dot(target_ng, target_ng) > 0.0f;
    const Vec3 end = on_surface
                         ? offset_ray_origin(target, target_ng, origin - target, coordinate_scale)
                         : target;
    // tmax is relative to the unnormalised direction: stop a hair before the end point whatever the
    // scene scale.
    return Ray{origin, end - origin, 1.0f - 1e-4f};
}

}  // namespace mvpl::trace
