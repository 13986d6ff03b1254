#pragma once
// The shadow casters as the shadow pass draws them (issue 14, "fewer triangles per face"): world
// positions only (12 bytes a vertex, indexed as the scene's meshes are, rather than the
// G-buffer's de-indexed 68-byte vertices), the triangles ordered along a Morton curve of their
// centroids and cut into clusters of consecutive triangles, each with a bounding sphere. A cube
// face then draws only the clusters that can reach its frustum and the VPL's lit half-space, as
// merged index ranges: a face sees about a sixth of the scene, a surface VPL half of it.
// CPU only and Vulkan-free (the tests check the culling against brute force).
#include <cstdint>
#include <vector>

#include "engine/core/math.h"
#include "engine/gpu/graphics_pipeline.h"
#include "engine/scene/scene.h"

namespace mvpl::render {

struct ShadowCluster {
    Vec3 centre{0.0f};
    float radius = 0.0f;
    uint32_t first_index = 0;  // into ShadowClusters::indices()
    uint32_t index_count = 0;
};

class ShadowClusters {
public:
    // Triangles per cluster: small enough that a face skips most of what it cannot see, large
    // enough that the draws per face stay few (the ranges of consecutive visible clusters are
    // merged into one draw each).
    static constexpr uint32_t kClusterTriangles = 256;

    // simplify_error > 0: a shadow proxy instead (issue 14, "coarser shadow geometry"): each mesh
    // of at least kProxyMinTriangles, its vertices welded by position, simplified by
    // meshoptimizer's edge-collapse simplifier until the next collapse would move the surface by
    // more than simplify_error × the mesh's extent.
    explicit ShadowClusters(const scene::Scene& scene,
                            uint32_t cluster_triangles = kClusterTriangles,
                            float simplify_error = 0.0f);
    static constexpr size_t kProxyMinTriangles = 4096;
    // The proxy's error bound, as a fraction of a mesh's extent (docs/results.md, "Shadow
    // proxy", for the measurement behind it).
    static constexpr float kProxyError = 1e-3f;

    const std::vector<Vec3>& positions() const { return m_positions; }
    const std::vector<uint32_t>& indices() const { return m_indices; }
    const std::vector<ShadowCluster>& clusters() const { return m_clusters; }
    size_t triangle_count() const { return m_indices.size() / 3; }

    // Replaces `out` by the index ranges to draw for cube face `face` (+X −X +Y −Y +Z −Z) of a
    // VPL at `position`: every cluster whose sphere may reach the face's frustum and, when
    // `lit_normal` is non-null, the half-space the VPL lights (n·(x − p) > 0), with a margin of
    // `margin_angle` radians (a texel of the face) so that the texels the shading pass reads
    // near the horizon keep their occluders. Never drops a triangle that can cover a texel.
    void visible_ranges(const Vec3& position, uint32_t face, const Vec3* lit_normal,
                        float margin_angle, std::vector<gpu::IndexRange>& out) const;

    // One range over every triangle.
    gpu::IndexRange all() const { return {0, uint32_t(m_indices.size())}; }

private:
    std::vector<Vec3> m_positions;
    std::vector<uint32_t> m_indices;
    std::vector<ShadowCluster> m_clusters;
};

}  // namespace mvpl::render
