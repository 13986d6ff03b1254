#pragma once
// The shadow casters as the shadow pass draws them (issue 14, "fewer triangles per face"): world
// positions only (12 bytes a vertex, indexed as the scene's meshes are, rather than the
// G-buffer's 84-byte vertices), cut into clusters of consecutive triangles along a
// Morton curve of their centroids, each with a bounding sphere. A cube face then draws only the
// clusters that can reach its frustum and the VPL's lit half-space, as merged index ranges: a face
// sees about a sixth of the scene, a surface VPL half of it.
//
// Levels of detail ("coarser shadow geometry"): each mesh of at least kLodMinTriangles is its
// own group, with its full triangles (level 0) and successively simplified copies (meshoptimizer's
// edge-collapse simplifier on the mesh welded by position), each with its error bound in world
// units. A VPL draws each group at the coarsest level whose error is below a fraction of a shadow
// texel's footprint at the group's distance (LodChoice): a mesh far from the VPL covers few
// texels, and its shadow does not need its triangles. The smaller meshes share one group of one
// level. CPU only and Vulkan-free (the tests check the culling against brute force).
#include <array>
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

// One level of a group: clusters [first_cluster, first_cluster + cluster_count).
struct ShadowLevel {
    uint32_t first_cluster = 0;
    uint32_t cluster_count = 0;
    uint32_t triangle_count = 0;
    float error = 0.0f;  // how far its surface may lie from the mesh's, world units (0: full)
};

// A mesh or a chunk of one with its levels, or the pooled small meshes (one level). The sphere
// (for culling) and the box (for the distance that chooses a level) bound every level: a
// simplified level keeps a subset of the full level's vertices.
struct ShadowGroup {
    Vec3 centre{0.0f};
    float radius = 0.0f;
    Vec3 lo{0.0f};
    Vec3 hi{0.0f};
    std::vector<ShadowLevel> levels;
    // Whether its mesh bounds a solid (closed_surface.h), and the mesh's box: a VPL outside the
    // box is outside the solid, and its shadow map needs only the mesh's front faces. The
    // chunks of a solid meet at the same edges at every level, so any mix of levels stays closed.
    bool solid = false;
    Vec3 solid_lo{0.0f};
    Vec3 solid_hi{0.0f};
};

// Which level a group draws: the coarsest whose error is at most
// max(error_per_distance × the distance from the VPL to the group's box, error_anywhere). The
// group a VPL lies in (distance 0) is drawn in full unless error_anywhere allows more.
struct LodChoice {
    float error_per_distance = 0.0f;
    float error_anywhere = 0.0f;
};

// Index ranges to draw, by kind: of full or simplified levels (which the shadow pass marks, so
// that the shading pass allows their error: ShadowPass::kLodFootprint), with both faces or only
// the faces towards the VPL (solids seen from outside).
struct CasterRanges {
    static constexpr size_t kSimplified = 1;
    static constexpr size_t kFrontOnly = 2;
    std::array<std::vector<gpu::IndexRange>, 4> by_kind;  // index: kSimplified | kFrontOnly bits
    const std::vector<gpu::IndexRange>& full() const { return by_kind[0]; }
    void clear() {
        for (std::vector<gpu::IndexRange>& r : by_kind)
            r.clear();
    }
};

class ShadowClusters {
public:
    // Triangles per cluster: small enough that a face skips most of what it cannot see, large
    // enough that the draws per face stay few (the ranges of consecutive visible clusters are
    // merged into one draw each).
    static constexpr uint32_t kClusterTriangles = 256;
    // Meshes below this many triangles are drawn as they are.
    static constexpr size_t kLodMinTriangles = 4096;
    // Meshes of at least twice this many are cut into chunks of about this many, each with its
    // own levels.
    static constexpr size_t kLodChunkTriangles = 8192;
    // The levels' error targets, as fractions of a mesh's extent (meshoptimizer's measure).
    // Level kProxyLevel (kProxyError) is the shadow proxy (docs/results.md, "Shadow culling and
    // the shadow proxy", for the measurement behind its error); level 1, at half its error,
    // serves VPLs a little nearer than the proxy's distance. Like every level, a VPL draws it only
    // as far away as LodChoice allows. Both are simplified from the full triangles; each further
    // level from the previous one, at kLodErrorStep × its error.
    static constexpr float kProxyError = 1e-3f;
    static constexpr float kFinestError = 0.5f * kProxyError;
    static constexpr uint32_t kProxyLevel = 2;
    static constexpr float kLodErrorStep = 4.0f;
    static constexpr uint32_t kMaxLevels = 7;

    // levels_of_detail false: every mesh one level, as it is.
    explicit ShadowClusters(const scene::Scene& scene,
                            uint32_t cluster_triangles = kClusterTriangles,
                            bool levels_of_detail = true);

    const std::vector<Vec3>& positions() const { return m_positions; }
    const std::vector<uint32_t>& indices() const { return m_indices; }
    const std::vector<ShadowCluster>& clusters() const { return m_clusters; }
    const std::vector<ShadowGroup>& groups() const { return m_groups; }
    // Triangles when every group draws `level` (or its coarsest).
    size_t triangle_count(uint32_t level = 0) const;

    // The level group g draws for a VPL at `position`.
    uint32_t level_for(const ShadowGroup& g, const Vec3& position, const LodChoice& lod) const;

    // Replaces `out` by the index ranges to draw for cube face `face` (+X −X +Y −Y +Z −Z) of a
    // VPL at `position`, each group at its level for `lod`: every cluster whose sphere may reach
    // the face's frustum and, when `lit_normal` is non-null, the half-space the VPL lights
    // (n·(x − p) > 0), with a margin of `margin_angle` radians (a texel of the face) so that the
    // texels the shading pass reads near the horizon keep their occluders. Never drops a
    // triangle of the chosen levels that can cover a texel.
    void visible_ranges(const Vec3& position, uint32_t face, const Vec3* lit_normal,
                        float margin_angle, const LodChoice& lod, CasterRanges& out) const;
    // Every cluster of each group's level for `lod` (no culling: orthographic maps, and faces
    // with culling off). at_infinity: a directional VPL, outside every solid.
    void level_ranges(const Vec3& position, const LodChoice& lod, CasterRanges& out,
                      bool at_infinity = false) const;

private:
    void add_level(ShadowGroup& group, const std::vector<uint32_t>& triangles, float error,
                   uint32_t cluster_triangles);

    std::vector<Vec3> m_positions;
    std::vector<uint32_t> m_indices;
    std::vector<ShadowCluster> m_clusters;
    std::vector<ShadowGroup> m_groups;
};

}  // namespace mvpl::render
