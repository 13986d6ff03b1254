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
// Avoiding Self-Intersection", Ray Tracing Gems ch. 6). Near the origin, where ULP steps become
// too fine, their constant offset takes over; `coordinate_scale` (Accel::coordinate_scale: the
// scene's largest |coordinate|) shrinks that constant and the region where it applies with a
// scene smaller than a metre, so that a 20 µm box is offset as a 2 m one is (issue 32: the
// constant 1.5·10⁻⁵ was the whole box). Larger scenes keep the constant: a point near the origin
// may lie on a triangle of any size there.
Vec3 offset_ray_origin(const Vec3& p, const Vec3& ng, const Vec3& direction,
                       float coordinate_scale);

// A ray leaving surface point p (geometric normal ng) in direction dir.
Ray spawn_ray(const Vec3& p, const Vec3& ng, const Vec3& dir, float coordinate_scale);
// A shadow ray from surface point p towards `target`, stopping just short of it. Pass the
// target's geometric normal when it lies on a surface (zero vector for a point light).
Ray spawn_ray_to(const Vec3& p, const Vec3& ng, const Vec3& target, const Vec3& target_ng,
                 float coordinate_scale);

}  // namespace mvpl::trace
