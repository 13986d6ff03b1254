#pragma once
// Virtual spherical lights on the CPU (the closed form of shaders/shared/virtual_sphere.h): which
// VPLs are spheres and the closure whose lobe is integrated over one. The CPU oracle
// (vpl_contribution.cpp) and the shading pass apply the same widening.
#include "engine/light/vpl.h"
#include "engine/material/closure.h"

namespace mvpl::light {

// Default VSL radius as a fraction of the scene's bounding-box diagonal (docs/results.md,
// "Virtual spherical lights"); 0 turns VSLs off (point VPLs).
inline constexpr float kDefaultVslRadius = 0.03f;

// Area and surface VPLs stand for a patch of surface and become spheres; point, spot and
// directional VPLs are the scene's own punctual lights and stay as they are.
inline bool is_spherical(VplType t) {
    return t == VplType::Area || t == VplType::Surface;
}

// The closure with its GGX α widened by spread2 (vsl_spread2); the closure itself when spread2
// is 0 or the closure has no microfacet lobe.
material::ClosureParams widen_closure(const material::ClosureParams& params, float spread2);

}  // namespace mvpl::light
