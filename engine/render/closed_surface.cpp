#include "engine/render/closed_surface.h"

#include <meshoptimizer.h>

#include <algorithm>

namespace mvpl::render {

bool bounds_solid(const std::vector<Vec3>& positions, const std::vector<uint32_t>& indices) {
    // Each directed edge (a, b) once, as a key; a closed, consistently wound surface holds (b, a)
    // exactly once too.
    std::vector<uint64_t> edges;
    edges.reserve(indices.size());
    double volume = 0.0;  // six times the signed volume (divergence theorem)
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
        const uint32_t v[3] = {indices[t], indices[t + 1], indices[t + 2]};
        // A triangle with a repeated vertex covers nothing; it may sit in a fan at a pole.
        if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) continue;
        for (int e = 0; e < 3; ++e)
            edges.push_back(uint64_t(v[e]) << 32 | v[(e + 1) % 3]);
        const glm::dvec3 a(positions[v[0]]), b(positions[v[1]]), c(positions[v[2]]);
        volume += glm::dot(a, glm::cross(b, c));
    }
    if (edges.empty() || !(volume > 0.0)) return false;
    std::sort(edges.begin(), edges.end());
    // A directed edge twice: two triangles wound the same way along it, or more than two on it.
    if (std::adjacent_find(edges.begin(), edges.end()) != edges.end()) return false;
    for (const uint64_t e : edges) {
        const uint64_t reverse = (e & 0xffffffffull) << 32 | e >> 32;
        if (!std::binary_search(edges.begin(), edges.end(), reverse)) return false;
    }
    return true;
}

bool bounds_solid(const scene::Mesh& mesh) {
    if (mesh.positions.empty()) return false;
    std::vector<uint32_t> remap(mesh.positions.size());
    meshopt_generateVertexRemap(remap.data(), mesh.indices.data(), mesh.indices.size(),
                                mesh.positions.data(), mesh.positions.size(), sizeof(Vec3));
    std::vector<uint32_t> indices(mesh.indices.size());
    meshopt_remapIndexBuffer(indices.data(), mesh.indices.data(), mesh.indices.size(),
                             remap.data());
    // The positions need not be compacted: the check only compares indices and sums volumes.
    return bounds_solid(mesh.positions, indices);
}

}  // namespace mvpl::render
