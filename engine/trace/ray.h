#pragma once
#include <limits>

#include "engine/core/math.h"

namespace mvpl::trace {

struct Ray {
    Vec3 origin;
    Vec3 direction;  // need not be unit; t is measured in its units
    float tmax = std::numeric_limits<float>::infinity();
};

// Moves a surface point off its triangle along the geometric normal, to the side `direction`
// leaves from, by a few ULPs of its coordinates (Wächter and Binder, "A Fast and Robust Method for
// Avoiding Self-Intersection", Ray Tracing Gems ch. 6). The offset scales with the position, so it
// works from millimetre to kilometre scenes with no scene-dependent epsilon.
Vec3 offset_ray_origin(const Vec3& p, const Vec3& ng, const Vec3& direction);

// A ray leaving surface point p (geometric normal ng) in direction dir.
Ray spawn_ray(const Vec3& p, const Vec3& ng, const Vec3& dir);
// A shadow ray from surface point p towards `target`, stopping just short of it. Pass the
// target's geometric normal when it lies on a surface (zero vector for a point light).
Ray spawn_ray_to(const Vec3& p, const Vec3& ng, const Vec3& target, const Vec3& target_ng);

}  // namespace mvpl::trace
