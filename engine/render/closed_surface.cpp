#include "engine/render/closed_surface.h"

#include <meshoptimizer.h>

#include <algorithm>

namespace mvpl::render {

bool bounds_solid(const std::vector<Vec3>& positions, const std::vector<uint32_t>& indices) {
    // The directed edges (a, b) grouped by a, as compressed rows: a few per vertex, so that
    // finding (b, a) among b's is a short scan (no sort: this runs on every large mesh at
    // start-up).
    const size_t vertices = positions.size();
    std::vector<uint32_t> first(vertices + 1, 0);
    double volume = 0.0;  // six times the signed volume (divergence theorem)
    size_t edges = 0;
    auto degenerate = [&](size_t t) {
        // A triangle with a repeated vertex covers nothing; it may sit in a fan at a pole.
        return indices[t] == indices[t + 1] || indices[t + 1] == indices[t + 2] ||
               indices[t + 2] == indices[t];
    };
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
        if (degenerate(t)) continue;
        for (int e = 0; e < 3; ++e) {
            if (indices[t + e] >= vertices) return false;
            ++first[indices[t + e] + 1];
        }
        edges += 3;
        const glm::dvec3 a(positions[indices[t]]), b(positions[indices[t + 1]]),
            c(positions[indices[t + 2]]);
        volume += glm::dot(a, glm::cross(b, c));
    }
    if (edges == 0 || !(volume > 0.0)) return false;
    for (size_t v = 0; v < vertices; ++v)
        first[v + 1] += first[v];
    std::vector<uint32_t> to(edges);
    std::vector<uint32_t> fill(first.begin(), first.end() - 1);
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
        if (degenerate(t)) continue;
        for (int e = 0; e < 3; ++e)
            to[fill[indices[t + e]]++] = indices[t + (e + 1) % 3];
    }
    // Closed and consistently wound: each directed edge (a, b) once, and (b, a) once. A directed
    // edge twice means two triangles wound the same way along it, or more than two on it.
    for (size_t a = 0; a < vertices; ++a) {
        for (uint32_t i = first[a]; i < first[a + 1]; ++i) {
            const uint32_t b = to[i];
            if (std::count(to.begin() + first[a], to.begin() + first[a + 1], b) != 1) return false;
            if (std::count(to.begin() + first[b], to.begin() + first[b + 1], uint32_t(a)) != 1)
                return false;
        }
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
