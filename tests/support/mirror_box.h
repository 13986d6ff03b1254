#pragma once
// A mirror sphere in a coloured box (issue 15's test scene for specular chains): the box
// [-1, 1]³ open towards +Z, white floor, ceiling and back wall, red left and green right wall, an
// area light of radiance 8 under the ceiling, a gold roughness-0 sphere of radius 0.5 at the
// origin; the camera on +Z looks at the sphere with a narrow field of view.
#include "engine/scene/scene.h"

namespace mvpl::test {

inline constexpr float kMirrorSphereRadius = 0.5f;

scene::Scene make_mirror_box();

}  // namespace mvpl::test
