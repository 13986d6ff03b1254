#pragma once
// Vector types and the few numeric helpers every subsystem shares. GLM supplies the algebra.
#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

namespace mvpl {

using Vec2 = glm::vec2;
using Vec3 = glm::vec3;
using Vec4 = glm::vec4;
using Mat3 = glm::mat3;
using Mat4 = glm::mat4;
using DVec3 = glm::dvec3;
using DMat4 = glm::dmat4;

inline constexpr float kPi = 3.14159265358979323846f;
inline constexpr float kInvPi = 0.31830988618379067154f;
inline constexpr float kInv2Pi = 0.15915494309189533577f;
inline constexpr float kInv4Pi = 0.07957747154594766788f;

inline float sqr(float x) {
    return x * x;
}
inline float safe_sqrt(float x) {
    return std::sqrt(std::max(x, 0.0f));
}
inline bool is_finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Orthonormal basis around a unit normal (Duff et al. 2017, "Building an Orthonormal Basis,
// Revisited"): continuous almost everywhere and free of the division by a small number that the
// classic Frisvad construction has near n = -z.
struct Frame {
    Vec3 s, t, n;

    Frame() : s(1, 0, 0), t(0, 1, 0), n(0, 0, 1) {}
    Frame(const Vec3& s_, const Vec3& t_, const Vec3& n_) : s(s_), t(t_), n(n_) {}
    explicit Frame(const Vec3& normal) : n(normal) {
        const float sign = std::copysign(1.0f, n.z);
        const float a = -1.0f / (sign + n.z);
        const float b = n.x * n.y * a;
        s = Vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
        t = Vec3(b, sign + n.y * n.y * a, -n.y);
    }
    Vec3 to_local(const Vec3& v) const {
        return Vec3(glm::dot(v, s), glm::dot(v, t), glm::dot(v, n));
    }
    Vec3 to_world(const Vec3& v) const { return s * v.x + t * v.y + n * v.z; }
};

// Trigonometry of a direction in a local frame whose z axis is the normal.
inline float cos_theta(const Vec3& w) {
    return w.z;
}
inline float abs_cos_theta(const Vec3& w) {
    return std::abs(w.z);
}
inline float cos2_theta(const Vec3& w) {
    return w.z * w.z;
}
inline float sin2_theta(const Vec3& w) {
    return std::max(0.0f, 1.0f - cos2_theta(w));
}
inline float tan2_theta(const Vec3& w) {
    return sin2_theta(w) / cos2_theta(w);
}
inline bool same_hemisphere(const Vec3& a, const Vec3& b) {
    return a.z * b.z > 0.0f;
}

}  // namespace mvpl
