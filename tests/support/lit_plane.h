#pragma once
// A Lambertian 4×4 m plane (albedo kLitPlaneAlbedo) under one punctual light, seen from above,
// and its analytic direct light: L = ρ/π · E, with E = I·falloff·cos θ / d² (point, spot) or
// E⊥·cos θ (directional). Shared by the direct-light tests of the path tracer, the oracle and the
// GPU pipeline.
#include "engine/scene/scene.h"

namespace mvpl::test {

inline constexpr float kLitPlaneAlbedo = 0.6f;

scene::Scene make_lit_plane(const scene::Light& light);
// Radiance leaving the plane point p (on y = 0) towards any direction, at max depth 2.
Rgb lit_plane_radiance(const scene::Light& light, const Vec3& p);

// The lights the direct-light tests use.
scene::Light example_point_light();
scene::Light example_spot_light();
scene::Light example_directional_light();

}  // namespace mvpl::test
