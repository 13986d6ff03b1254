#pragma once
// Warps from the unit square to the domains the light transport needs, with their densities.
#include "engine/core/math.h"

namespace mvpl {

// Shirley–Chiu concentric map to the unit disk.
Vec2 sample_concentric_disk(const Vec2& u);
// Cosine-weighted hemisphere around +z (Malley's method); pdf = cos θ / π.
Vec3 sample_cosine_hemisphere(const Vec2& u);
inline float cosine_hemisphere_pdf(float cos_theta) {
    return cos_theta > 0.0f ? cos_theta * kInvPi : 0.0f;
}
// Uniform direction on the unit sphere; pdf = 1 / 4π.
Vec3 sample_uniform_sphere(const Vec2& u);
// Uniform direction in the cone around +z of half-angle acos(cos_max); pdf = 1 / (2π(1 − cos_max)).
Vec3 sample_uniform_cone(const Vec2& u, float cos_max);
// Barycentric coordinates (b1, b2) of a uniform point on a triangle (Heitz 2019's low-distortion
// map); the point is (1 − b1 − b2)·p0 + b1·p1 + b2·p2.
Vec2 sample_uniform_triangle(const Vec2& u);

// Power heuristic with β = 2 (Veach 1997).
inline float power_heuristic(float pdf_a, float pdf_b) {
    const float a = pdf_a * pdf_a;
    const float b = pdf_b * pdf_b;
    return a + b > 0.0f ? a / (a + b) : 0.0f;
}

}  // namespace mvpl
