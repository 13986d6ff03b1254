#pragma once
// One glTF primitive as a world-space triangle mesh.
#include <cstdint>

#include "engine/core/math.h"
#include "engine/scene/gltf_document.h"
#include "engine/scene/scene.h"

namespace mvpl::scene::gltf {

// What the scene holds so far; instancing lets a small file ask for a lot, so every primitive is
// charged here before anything is allocated for it.
struct GeometryBudget {
    uint64_t triangles = 0;
    uint64_t vertices = 0;
};

// Builds primitive `primitive` of mesh `mesh`, placed by node `node` with transform `world`, into
// `out` (name, positions, normals, uvs, tangents, indices; not the material). Returns false for
// point and line primitives and for primitives without a triangle, leaving `out` alone.
bool build_primitive_mesh(const Document& doc, int mesh, int primitive, int node,
                          const DMat4& world, GeometryBudget& budget, Mesh& out);

}  // namespace mvpl::scene::gltf
