#pragma once
// The scenes of test_caustic_tracer.cpp: light onto a diffuse floor through a glass pane, and
// off a near-mirror.
#include "engine/scene/scene.h"

namespace mvpl::integrator {

// The pane scene's sizes: the pane halfway up, its half width, the area light's half width.
inline constexpr float kPaneY = 0.5f;
inline constexpr float kPaneHalf = 0.5f;
inline constexpr float kLightHalf = 0.25f;

// A diffuse floor (y = 0) and back wall (z = −1.5) under a downward area light (0.5 × 0.5, y = 1,
// radiance 4) with a thin smooth glass pane (1 × 1, transmission 1, IOR 1.5) halfway between
// light and floor, and a point light (intensity 1) low at the side, below the pane's plane; the
// camera, below that plane too, sees the floor under the pane without looking through it. At max
// depth 3 that floor is lit through the pane (light → glass → floor → eye: the caustic tracer's),
// by the point light directly and through the wall (the VPLs').
// `glass` false: the pane is diffuse (a diffuse-only scene).
scene::Scene make_pane_scene(bool glass = true);

// A near-mirror (metal, roughness 0.05: the chains' class) standing on the floor beside a
// downward area light: the light it reflects onto the floor goes to the caustic tracer instead of
// VPLs on the mirror, so that it is counted once. (VPLs left on the mirror too would count it
// twice in expectation, but their 10⁻³ rad lobes are heavy-tailed: at 512 paths they add almost
// nothing in most runs — printed — which is why the light tracer carries that light.) The camera
// at x = −1 sees the floor in front of the mirror before the mirror's plane x = 0.8.
scene::Scene make_mirror_scene();

}  // namespace mvpl::integrator
