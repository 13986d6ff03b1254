#pragma once
// PLY meshes (Turk 1994; the format of the Stanford scanning repository): ascii and binary
// little- and big-endian. Reads the `vertex` element's x, y, z (and nx, ny, nz when all three
// are present) and the `face` element's `vertex_indices` (or `vertex_index`) list; polygons are
// fan-triangulated, every other element and property is skipped.
#include <string>

#include "engine/scene/scene.h"

namespace mvpl::scene {

// One mesh with the default grey diffuse material, a camera framing its bounds and no light.
// Throws InputError naming the file and the defect (bad header, truncated data, an index out of
// range, a non-finite vertex, ...); allocates no more than the file's size can justify.
Scene load_ply(const std::string& path);

// The mesh alone, in the file's coordinates: positions, the normals when the file has nx, ny and
// nz, the texture coordinates when it has u, v (or s, t, texture_u, texture_v, texture_s,
// texture_t), and fan-triangulated indices. Same checks and errors as load_ply.
Mesh read_ply_mesh(const std::string& path);

}  // namespace mvpl::scene
