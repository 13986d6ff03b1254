#pragma once
// Mitsuba's analytic shapes as triangle meshes in their object space, with Mitsuba's
// parameterisation (uv) and outward normals. The curved ones are tessellated finely enough that
// the area (and so an area light's power) is within 10⁻³ of the analytic shape's.
#include "engine/scene/scene.h"

namespace mvpl::scene::mitsuba {

// [−1, 1]² in the z = 0 plane, normal +z, uv = (x + 1, y + 1) / 2.
Mesh rectangle_mesh();
// [−1, 1]³, six faces with their own normals and a [0, 1]² uv each.
Mesh cube_mesh();
// The unit sphere about the origin; u = φ / 2π about +z, v = θ / π from +z.
Mesh sphere_mesh();
// The unit disk in the z = 0 plane, normal +z; uv = (r, φ / 2π).
Mesh disk_mesh();
// The open tube of radius 1 from z = 0 to z = 1, normals outward; uv = (φ / 2π, z).
Mesh cylinder_mesh();

}  // namespace mvpl::scene::mitsuba
