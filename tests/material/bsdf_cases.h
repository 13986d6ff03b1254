#pragma once
// Closures and directions shared by the material tests.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "engine/core/rng.h"
#include "engine/material/closure.h"

namespace mvpl::material::test {

inline constexpr float kDegree = kPi / 180.0f;

// Unit direction at polar angle theta (radians from +z) and azimuth phi.
inline Vec3 spherical_direction(float theta, float phi) {
    return Vec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
}

// wo at polar angle theta_deg with an azimuth that is not an axis, so that a sampler or pdf that
// silently assumes φo = 0 shows.
inline Vec3 outgoing(float theta_deg) {
    return spherical_direction(theta_deg * kDegree, 0.7f);
}

// Uniform direction on the upper hemisphere (pdf 1 / 2π).
inline Vec3 uniform_hemisphere(Rng& rng) {
    const float z = rng.next_float();
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const float phi = 2.0f * kPi * rng.next_float();
    return Vec3(r * std::cos(phi), r * std::sin(phi), z);
}

inline ClosureParams lambertian(const Rgb& base) {
    ClosureParams p;
    p.base_color = base;
    p.metallic = 0.0f;
    p.specular = 0.0f;
    return p;
}

inline ClosureParams conductor(const Rgb& base, float roughness) {
    ClosureParams p;
    p.base_color = base;
    p.metallic = 1.0f;
    p.roughness = roughness;
    return p;
}

inline ClosureParams dielectric(const Rgb& base, float roughness, float ior = 1.5f,
                                float specular = 1.0f, const Rgb& specular_color = Rgb(1.0f)) {
    ClosureParams p;
    p.base_color = base;
    p.metallic = 0.0f;
    p.roughness = roughness;
    p.ior = ior;
    p.specular = specular;
    p.specular_color = specular_color;
    return p;
}

inline ClosureParams mixture(const Rgb& base, float roughness, float metallic) {
    ClosureParams p = dielectric(base, roughness);
    p.metallic = metallic;
    return p;
}

struct NamedClosure {
    std::string name;
    ClosureParams params;
};

// One of each closure type, coloured, for the property tests.
inline std::vector<NamedClosure> closure_zoo() {
    return {
        {"lambertian", lambertian(Rgb(0.8f, 0.5f, 0.2f))},
        {"conductor_r0.05", conductor(Rgb(0.95f, 0.64f, 0.54f), 0.05f)},
        {"conductor_r0.4", conductor(Rgb(0.95f, 0.64f, 0.54f), 0.4f)},
        {"conductor_r1", conductor(Rgb(0.9f), 1.0f)},
        {"dielectric_r0.1", dielectric(Rgb(0.2f, 0.4f, 0.8f), 0.1f)},
        {"dielectric_r0.6", dielectric(Rgb(0.7f, 0.7f, 0.1f), 0.6f)},
        {"dielectric_colored_specular",
         dielectric(Rgb(0.5f), 0.3f, 1.8f, 0.7f, Rgb(1.5f, 0.5f, 0.2f))},
        {"mixture_m0.5", mixture(Rgb(0.6f, 0.3f, 0.9f), 0.35f, 0.5f)},
        {"mixture_m0.2_smooth", mixture(Rgb(0.9f, 0.9f, 0.2f), 0.02f, 0.2f)},
    };
}

}  // namespace mvpl::material::test
