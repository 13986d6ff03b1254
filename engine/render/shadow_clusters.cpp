#include "engine/render/shadow_clusters.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "engine/render/closed_surface.h"

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

// The box of the given points, and a sphere around them: the box's centre, with the radius
// rounded up so that it contains every point.
struct Bound {
    Vec3 lo{INFINITY};
    Vec3 hi{-INFINITY};
    Vec3 centre{0.0f};
    float radius = 0.0f;
};

Bound bound(const std::vector<Vec3>& positions, const uint32_t* indices, size_t count) {
    Bound b;
    for (size_t i = 0; i < count; ++i) {
        b.lo = glm::min(b.lo, positions[indices[i]]);
        b.hi = glm::max(b.hi, positions[indices[i]]);
    }
    b.centre = 0.5f * (b.lo + b.hi);
    for (size_t i = 0; i < count; ++i)
        b.radius = std::max(b.radius, glm::length(positions[indices[i]] - b.centre));
    b.radius = b.radius * (1.0f + 1e-5f) + 1e-30f;
    return b;
}

// A group's sphere and box.
void bound_group(const std::vector<Vec3>& positions, const std::vector<uint32_t>& indices,
                 ShadowGroup& group) {
    const Bound b = bound(positions, indices.data(), indices.size());
    group.centre = b.centre;
    group.radius = b.radius;
    group.lo = b.lo;
    group.hi = b.hi;
}

// Whether a sphere may reach cube face `face` of a VPL at `position` and, with a normal, the
// half-space it lights, tilted down by the margin.
bool sphere_visible(const Vec3& centre, float radius, const Vec3& position, uint32_t face,
                    const Vec3* lit_normal, float sin_margin) {
    const int axis = int(face / 2);
    const float sign = face % 2 == 0 ? 1.0f : -1.0f;
    const int u = (axis + 1) % 3;
    const int v = (axis + 2) % 3;
    // The face's frustum: sign·r_axis ≥ |r_u| and ≥ |r_v|; its four planes through the VPL have
    // unit normals (sign·e_axis ± e_u)/√2 and (sign·e_axis ± e_v)/√2.
    constexpr float kInvSqrt2 = 0.70710678f;
    const Vec3 r = centre - position;
    const float along = sign * r[axis];
    // Slack: the sphere plus the relative rounding of r (positions far from the origin).
    const float slack = radius + 1e-5f * (std::abs(r.x) + std::abs(r.y) + std::abs(r.z));
    if ((along - std::abs(r[u])) * kInvSqrt2 < -slack) return false;
    if ((along - std::abs(r[v])) * kInvSqrt2 < -slack) return false;
    // A sphere wholly below the plane tilted down by the margin is never looked up.
    return !lit_normal ||
           glm::dot(*lit_normal, r) >= -slack - sin_margin * (glm::length(r) + radius);
}

// Which of CasterRanges' lists a level of g goes to for a VPL at `position` (at infinity: a
// directional one).
size_t caster_kind(const ShadowGroup& g, const ShadowLevel& level, const Vec3& position,
                   bool at_infinity) {
    size_t kind = level.error > 0.0f ? CasterRanges::kSimplified : 0;
    if (g.solid) {
        // Strictly outside the solid's box, by a margin for the rounding of a VPL that lies on
        // the solid's extreme point.
        const Vec3 margin = 1e-5f * (g.solid_hi - g.solid_lo) + 1e-30f;
        const bool outside = glm::any(glm::lessThan(position, g.solid_lo - margin)) ||
                             glm::any(glm::greaterThan(position, g.solid_hi + margin));
        if (at_infinity || outside) kind |= CasterRanges::kFrontOnly;
    }
    return kind;
}

void append_range(std::vector<gpu::IndexRange>& out, const ShadowCluster& c) {
    if (!out.empty() && out.back().first_index + out.back().index_count == c.first_index) {
        out.back().index_count += c.index_count;
    } else {
        out.push_back({c.first_index, c.index_count});
    }
}

// meshoptimizer's error measures how far the kept vertices moved from the planes of the triangles
// they replace; the new triangles' interiors stray farther (on a sphere, whose vertices stay on
// it, up to 1.8× at the first level, 1.1–1.3× at coarser ones: tests/render/test_shadow_lod.cpp).
constexpr float kQuadricErrorFactor = 2.0f;

// The levels of a large mesh (or a chunk of one) after its full triangles, each as indices into
// `welded`, with meshoptimizer's estimate of its error in world units.
struct SimplifiedLevel {
    std::vector<uint32_t> indices;
    float error = 0.0f;
};

// indices: the chunk's triangles, into `welded`; mesh_scale: the mesh's meshopt_simplifyScale,
// which the levels' target errors (kProxyError, …) are fractions of.
std::vector<SimplifiedLevel> simplified_levels(const std::vector<Vec3>& welded,
                                               const std::vector<uint32_t>& indices,
                                               float mesh_scale, bool lock_border) {
    // The chunk's own vertices: meshoptimizer's work and memory grow with the vertex buffer it
    // is given, and a chunk uses a few percent of a large mesh's.
    std::vector<uint32_t> used(indices);
    std::sort(used.begin(), used.end());
    used.erase(std::unique(used.begin(), used.end()), used.end());
    std::vector<Vec3> local(used.size());
    for (size_t i = 0; i < used.size(); ++i)
        local[i] = welded[used[i]];
    std::vector<uint32_t> local_indices(indices.size());
    for (size_t i = 0; i < indices.size(); ++i)
        local_indices[i] =
            uint32_t(std::lower_bound(used.begin(), used.end(), indices[i]) - used.begin());
    const float scale = meshopt_simplifyScale(&local[0].x, local.size(), sizeof(Vec3));
    std::vector<SimplifiedLevel> levels;
    std::vector<uint32_t> input;
    float input_error = 0.0f;  // world units
    for (uint32_t k = 1; k < ShadowClusters::kMaxLevels; ++k) {
        // Levels up to the proxy from the full triangles (a chain through the finest level made
        // the proxy larger); the coarser ones from the previous level, so that a level's distance
        // from the mesh is at most the sum of the steps' errors (each measured against its own
        // input, relative to `scale`).
        float target = ShadowClusters::kProxyError * mesh_scale;
        if (k < ShadowClusters::kProxyLevel) target = ShadowClusters::kFinestError * mesh_scale;
        for (uint32_t j = ShadowClusters::kProxyLevel; j < k; ++j)
            target *= ShadowClusters::kLodErrorStep;
        if (k <= ShadowClusters::kProxyLevel) {
            input = local_indices;
            input_error = 0.0f;
        }
        std::vector<uint32_t> out(input.size());
        float step_error = 0.0f;
        const size_t count =
            meshopt_simplify(out.data(), input.data(), input.size(), &local[0].x, local.size(),
                             sizeof(Vec3), 3, (target - input_error) / scale,
                             lock_border ? unsigned(meshopt_SimplifyLockBorder) : 0u, &step_error);
        if (count == 0) break;  // nothing left at that error: the coarser levels would be empty
        // A level that saves less than a quarter is not worth its clusters; those up to the
        // surface VPLs' proxy are always kept, so that the proxy is the same level everywhere.
        if (k > ShadowClusters::kProxyLevel && double(count) > 0.75 * double(input.size()))
            continue;
        out.resize(count);
        input = out;
        input_error += step_error * scale;
        for (uint32_t& i : out)
            i = used[i];
        levels.push_back({std::move(out), input_error});
        if (count <= 3 * 16) break;
    }
    return levels;
}

// The order of triangles along a Morton curve of their centroids.
std::vector<uint32_t> morton_order(const std::vector<Vec3>& positions,
                                   const std::vector<uint32_t>& triangles) {
    const size_t count = triangles.size() / 3;
    Vec3 lo(INFINITY);
    Vec3 hi(-INFINITY);
    std::vector<Vec3> centroids(count);
    for (size_t t = 0; t < count; ++t) {
        centroids[t] = (positions[triangles[3 * t]] + positions[triangles[3 * t + 1]] +
                        positions[triangles[3 * t + 2]]) /
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
    return order;
}

}  // namespace

void ShadowClusters::add_level(ShadowGroup& group, const std::vector<uint32_t>& triangles,
                               float error, uint32_t cluster_triangles) {
    const size_t count = triangles.size() / 3;
    const std::vector<uint32_t> order = morton_order(m_positions, triangles);
    const size_t first_index = m_indices.size();
    for (const uint32_t t : order) {
        for (int k = 0; k < 3; ++k)
            m_indices.push_back(triangles[3 * t + k]);
    }
    ShadowLevel level;
    level.first_cluster = uint32_t(m_clusters.size());
    level.triangle_count = uint32_t(count);
    level.error = error;
    const uint32_t per_cluster = std::max(cluster_triangles, 1u);
    for (size_t first = 0; first < count; first += per_cluster) {
        const size_t last = std::min(count, first + per_cluster);
        ShadowCluster c;
        const Bound b = bound(m_positions, &m_indices[first_index + 3 * first], 3 * (last - first));
        c.centre = b.centre;
        c.radius = b.radius;
        c.first_index = uint32_t(first_index + 3 * first);
        c.index_count = uint32_t(3 * (last - first));
        m_clusters.push_back(c);
    }
    level.cluster_count = uint32_t(m_clusters.size()) - level.first_cluster;
    group.levels.push_back(level);
}

ShadowClusters::ShadowClusters(const scene::Scene& scene, uint32_t cluster_triangles,
                               bool levels_of_detail) {
    ShadowGroup small;
    std::vector<uint32_t> small_triangles;  // three indices each, into m_positions
    for (const scene::Mesh& mesh : scene.meshes) {
        // Masked and blended meshes cast shadows through ShadowPass's alpha-tested draws.
        if (mesh.material >= 0 && size_t(mesh.material) < scene.materials.size() &&
            scene.materials[size_t(mesh.material)].alpha_mode != scene::AlphaMode::Opaque)
            continue;
        const uint32_t base = uint32_t(m_positions.size());
        m_positions.insert(m_positions.end(), mesh.positions.begin(), mesh.positions.end());
        std::vector<uint32_t> full(mesh.indices.size());
        for (size_t i = 0; i < full.size(); ++i)
            full[i] = base + mesh.indices[i];
        if (!levels_of_detail || mesh.triangle_count() < kLodMinTriangles) {
            small_triangles.insert(small_triangles.end(), full.begin(), full.end());
            continue;
        }
        // Seams of normals and texture coordinates split vertices that shadows need not tell
        // apart; welded, the simplifier sees one surface instead of patches with locked borders.
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
        const float scale = meshopt_simplifyScale(&welded[0].x, welded.size(), sizeof(Vec3));
        const uint32_t welded_base = uint32_t(m_positions.size());
        m_positions.insert(m_positions.end(), welded.begin(), welded.end());
        // A mesh much larger than a chunk is cut into chunks along a Morton curve, each its own
        // group, so that the part of a large model near a VPL keeps its triangles while the rest
        // is simplified. Their borders are locked (meshopt_SimplifyLockBorder): every level of a
        // chunk meets its neighbours' at the same edges, without cracks for light to pass.
        const size_t triangles = mesh.triangle_count();
        const size_t chunks =
            triangles >= 2 * kLodChunkTriangles ? triangles / kLodChunkTriangles : 1;
        const std::vector<uint32_t> order = morton_order(welded, indices);
        const bool solid = bounds_solid(welded, indices);
        const Bound mesh_box = bound(m_positions, full.data(), full.size());
        for (size_t k = 0; k < chunks; ++k) {
            std::vector<uint32_t> chunk_full;
            std::vector<uint32_t> chunk_welded;
            for (size_t o = k * triangles / chunks; o < (k + 1) * triangles / chunks; ++o) {
                for (int v = 0; v < 3; ++v) {
                    chunk_full.push_back(full[3 * size_t(order[o]) + v]);
                    chunk_welded.push_back(indices[3 * size_t(order[o]) + v]);
                }
            }
            ShadowGroup group;
            bound_group(m_positions, chunk_full, group);
            group.solid = solid;
            group.solid_lo = mesh_box.lo;
            group.solid_hi = mesh_box.hi;
            add_level(group, chunk_full, 0.0f, cluster_triangles);
            for (SimplifiedLevel& level :
                 simplified_levels(welded, chunk_welded, scale, chunks > 1)) {
                for (uint32_t& i : level.indices)
                    i += welded_base;
                add_level(group, level.indices, kQuadricErrorFactor * level.error,
                          cluster_triangles);
            }
            m_groups.push_back(std::move(group));
        }
    }
    if (!small_triangles.empty()) {
        bound_group(m_positions, small_triangles, small);
        add_level(small, small_triangles, 0.0f, cluster_triangles);
        m_groups.push_back(std::move(small));
    }
}

size_t ShadowClusters::triangle_count(uint32_t level) const {
    size_t count = 0;
    for (const ShadowGroup& g : m_groups)
        count += g.levels[std::min<size_t>(level, g.levels.size() - 1)].triangle_count;
    return count;
}

uint32_t ShadowClusters::level_for(const ShadowGroup& g, const Vec3& position,
                                   const LodChoice& lod) const {
    const float distance = glm::length(glm::max(glm::max(g.lo - position, position - g.hi), 0.0f));
    const float allowed = std::max(lod.error_per_distance * distance, lod.error_anywhere);
    uint32_t level = 0;
    // Without an allowance, not even a level that happens to be exact (a flat mesh's) is taken:
    // levels of detail off draw what they drew before.
    if (!(allowed > 0.0f)) return level;
    while (level + 1 < g.levels.size() && g.levels[level + 1].error <= allowed)
        ++level;
    return level;
}

void ShadowClusters::visible_ranges(const Vec3& position, uint32_t face, const Vec3* lit_normal,
                                    float margin_angle, const LodChoice& lod,
                                    CasterRanges& out) const {
    out.clear();
    const float sin_margin = std::sin(std::min(margin_angle, 1.5f));
    for (const ShadowGroup& g : m_groups) {
        if (!sphere_visible(g.centre, g.radius, position, face, lit_normal, sin_margin)) continue;
        const ShadowLevel& level = g.levels[level_for(g, position, lod)];
        std::vector<gpu::IndexRange>& ranges = out.by_kind[caster_kind(g, level, position, false)];
        for (uint32_t i = 0; i < level.cluster_count; ++i) {
            const ShadowCluster& c = m_clusters[level.first_cluster + i];
            if (sphere_visible(c.centre, c.radius, position, face, lit_normal, sin_margin))
                append_range(ranges, c);
        }
    }
}

void ShadowClusters::level_ranges(const Vec3& position, const LodChoice& lod, CasterRanges& out,
                                  bool at_infinity) const {
    out.clear();
    for (const ShadowGroup& g : m_groups) {
        const ShadowLevel& level = g.levels[level_for(g, position, lod)];
        std::vector<gpu::IndexRange>& ranges =
            out.by_kind[caster_kind(g, level, position, at_infinity)];
        for (uint32_t i = 0; i < level.cluster_count; ++i)
            append_range(ranges, m_clusters[level.first_cluster + i]);
    }
}

}  // namespace mvpl::render
