#include "engine/render/shadow_clusters.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace mvpl::render {

namespace {

// Spreads the low 21 bits of x so that two zero bits follow each (3D Morton code).
uint64_t spread_bits(uint64_t x) {
    x &= 0x1fffff;
    x = (x | x << 32) & 0x1f00000000ffffull;
    x = (x | x << 16) & 0x1f0000ff0000ffull;
    x = (x | x << 8) & 0x100f00f00f00f00full;
    x = (x | x << 4) & 0x10c30c30c30c30c3ull;
    x = (x | x << 2) & 0x1249249249249249ull;
    return x;
}

uint64_t morton_code(const Vec3& p, const Vec3& lo, const Vec3& extent) {
    uint64_t code = 0;
    for (int a = 0; a < 3; ++a) {
        const float t = extent[a] > 0.0f ? (p[a] - lo[a]) / extent[a] : 0.0f;
        const uint64_t q = uint64_t(std::clamp(t, 0.0f, 1.0f) * float((1u << 21) - 1));
        code |= spread_bits(q) << a;
    }
    return code;
}

// Appends the mesh's positions to `positions` and its triangles, as indices into them, to
// `triangles`: welded and simplified when `simplify_error` > 0 and the mesh is large enough.
void add_mesh(const scene::Mesh& mesh, float simplify_error, std::vector<Vec3>& positions,
              std::vector<uint32_t>& triangles) {
    const uint32_t base = uint32_t(positions.size());
    if (!(simplify_error > 0.0f) || mesh.triangle_count() < ShadowClusters::kProxyMinTriangles) {
        positions.insert(positions.end(), mesh.positions.begin(), mesh.positions.end());
        for (const uint32_t i : mesh.indices)
            triangles.push_back(base + i);
        return;
    }
    // Seams of normals and texture coordinates split vertices that shadows need not tell apart;
    // welded, the simplifier sees one surface instead of patches with locked borders.
    std::vector<uint32_t> remap(mesh.positions.size());
    const size_t unique =
        meshopt_generateVertexRemap(remap.data(), mesh.indices.data(), mesh.indices.size(),
                                    mesh.positions.data(), mesh.positions.size(), sizeof(Vec3));
    std::vector<Vec3> welded(unique);
    meshopt_remapVertexBuffer(welded.data(), mesh.positions.data(), mesh.positions.size(),
                              sizeof(Vec3), remap.data());
    std::vector<uint32_t> indices(mesh.indices.size());
    meshopt_remapIndexBuffer(indices.data(), mesh.indices.data(), mesh.indices.size(),
                             remap.data());
    // The error bound decides where it stops, not the triangle count.
    std::vector<uint32_t> simplified(indices.size());
    const size_t count =
        meshopt_simplify(simplified.data(), indices.data(), indices.size(), &welded[0].x,
                         welded.size(), sizeof(Vec3), 3, simplify_error, 0, nullptr);
    positions.insert(positions.end(), welded.begin(), welded.end());
    for (size_t i = 0; i < count; ++i)
        triangles.push_back(base + simplified[i]);
}

}  // namespace

ShadowClusters::ShadowClusters(const scene::Scene& scene, uint32_t cluster_triangles,
                               float simplify_error) {
    std::vector<uint32_t> triangles;  // three indices each, into m_positions
    for (const scene::Mesh& mesh : scene.meshes) {
        // Masked and blended meshes cast shadows through ShadowPass's alpha-tested draws.
        if (mesh.material >= 0 && size_t(mesh.material) < scene.materials.size() &&
            scene.materials[size_t(mesh.material)].alpha_mode != scene::AlphaMode::Opaque)
            continue;
        add_mesh(mesh, simplify_error, m_positions, triangles);
    }
    const size_t count = triangles.size() / 3;
    Vec3 lo(INFINITY);
    Vec3 hi(-INFINITY);
    std::vector<Vec3> centroids(count);
    for (size_t t = 0; t < count; ++t) {
        centroids[t] = (m_positions[triangles[3 * t]] + m_positions[triangles[3 * t + 1]] +
                        m_positions[triangles[3 * t + 2]]) /
                       3.0f;
        lo = glm::min(lo, centroids[t]);
        hi = glm::max(hi, centroids[t]);
    }
    std::vector<uint64_t> codes(count);
    for (size_t t = 0; t < count; ++t)
        codes[t] = morton_code(centroids[t], lo, hi - lo);
    std::vector<uint32_t> order(count);
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(),
                     [&codes](uint32_t a, uint32_t b) { return codes[a] < codes[b]; });
    m_indices.reserve(triangles.size());
    for (const uint32_t t : order) {
        for (int k = 0; k < 3; ++k)
            m_indices.push_back(triangles[3 * t + k]);
    }
    const uint32_t per_cluster = std::max(cluster_triangles, 1u);
    for (size_t first = 0; first < count; first += per_cluster) {
        const size_t last = std::min(count, first + per_cluster);
        Vec3 c_lo(INFINITY);
        Vec3 c_hi(-INFINITY);
        for (size_t i = 3 * first; i < 3 * last; ++i) {
            c_lo = glm::min(c_lo, m_positions[m_indices[i]]);
            c_hi = glm::max(c_hi, m_positions[m_indices[i]]);
        }
        ShadowCluster c;
        c.centre = 0.5f * (c_lo + c_hi);
        for (size_t i = 3 * first; i < 3 * last; ++i)
            c.radius = std::max(c.radius, glm::length(m_positions[m_indices[i]] - c.centre));
        // Rounding of the centre and of the distances: the sphere must contain every vertex.
        c.radius = c.radius * (1.0f + 1e-5f) + 1e-30f;
        c.first_index = uint32_t(3 * first);
        c.index_count = uint32_t(3 * (last - first));
        m_clusters.push_back(c);
    }
}

void ShadowClusters::visible_ranges(const Vec3& position, uint32_t face, const Vec3* lit_normal,
                                    float margin_angle, std::vector<gpu::IndexRange>& out) const {
    out.clear();
    const int axis = int(face / 2);
    const float sign = face % 2 == 0 ? 1.0f : -1.0f;
    const int u = (axis + 1) % 3;
    const int v = (axis + 2) % 3;
    // The face's frustum: sign·r_axis ≥ |r_u| and ≥ |r_v|; its four planes through the VPL have
    // unit normals (sign·e_axis ± e_u)/√2 and (sign·e_axis ± e_v)/√2.
    constexpr float kInvSqrt2 = 0.70710678f;
    const float sin_margin = std::sin(std::min(margin_angle, 1.5f));
    for (const ShadowCluster& c : m_clusters) {
        const Vec3 r = c.centre - position;
        const float along = sign * r[axis];
        // Slack: the sphere plus the relative rounding of r (positions far from the origin).
        const float slack = c.radius + 1e-5f * (std::abs(r.x) + std::abs(r.y) + std::abs(r.z));
        const bool in_frustum = (along - std::abs(r[u])) * kInvSqrt2 >= -slack &&
                                (along - std::abs(r[v])) * kInvSqrt2 >= -slack;
        bool lit = true;
        if (lit_normal) {
            // A sphere wholly below the plane tilted down by the margin is never looked up.
            lit = glm::dot(*lit_normal, r) >= -slack - sin_margin * (glm::length(r) + c.radius);
        }
        if (!in_frustum || !lit) continue;
        if (!out.empty() && out.back().first_index + out.back().index_count == c.first_index) {
            out.back().index_count += c.index_count;
        } else {
            out.push_back({c.first_index, c.index_count});
        }
    }
}

}  // namespace mvpl::render
