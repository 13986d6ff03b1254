#pragma once
// Whether a triangle mesh bounds a solid (issue 14, shadow casters that draw only their front
// faces): every edge shared by exactly two triangles that run it in opposite directions (a closed,
// consistently wound 2-manifold, its degenerate triangles aside), and a positive signed volume
// (the windings face outwards). For such a mesh a ray from a point outside it enters through a
// front face before it meets any back face, so a shadow map seen from outside holds the same
// nearest distances without its back faces. CPU only and Vulkan-free.
#include <cstdint>
#include <vector>

#include "engine/core/math.h"
#include "engine/scene/scene.h"

namespace mvpl::render {

// positions: welded (one index per distinct position), so that seams of normals or texture
// coordinates do not open the surface; indices: three per triangle.
bool bounds_solid(const std::vector<Vec3>& positions, const std::vector<uint32_t>& indices);
// The same for a scene mesh, welded by position first.
bool bounds_solid(const scene::Mesh& mesh);

}  // namespace mvpl::render
