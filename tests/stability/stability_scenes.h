#pragma once
// Programmatic scenes for the stability suite.
#include "engine/scene/scene.h"

namespace mvpl::test {

// A diffuse floor and back wall under a point light: direct light and one-bounce light from the
// wall, so that a point light's surface VPLs matter too.
scene::Scene make_point_light_room();

// Multiplies every emitter (punctual intensities and emissive materials) by k.
void scale_emission(scene::Scene& scene, float k);

// make_point_light_room with triangles that break naive code placed where they are lit and seen:
// zero-area ones (three collinear vertices; two and three coincident vertices) and slivers whose
// width is a few ulps of their length.
scene::Scene make_degenerate_scene();

// A near-mirror metal floor (roughness 1e-3, GGX α = 10⁻⁶ clamped to the closure's minimum) and a
// diffuse wall under a point light, seen at a grazing angle (the camera 2° above the floor).
scene::Scene make_near_mirror_scene();

}  // namespace mvpl::test
