#pragma once
// Pass 2 (docs/design.md, "GPU passes"): the distance from each VPL of a batch to the nearest
// surface in every direction, as cube maps in an RG32F 2D array (cube i = batch[i], layers 6i … 6i
// + 5 in the order +X −X +Y −Y +Z −Z). Six single-layer passes per cube (the fastest on lavapipe;
// multiview writes wrong layers there). Not a cube-map view: the shading pass selects face and
// texel itself as cube sampling would (it needs the texel's centre anyway) and loads the texel as
// a storage image, which on lavapipe costs a fraction of a samplerCubeArray lookup. Area and
// Surface VPLs skip the faces that lie wholly behind their normal (they never light those
// directions; the texels keep stale values that are never read).
// Vulkan-free to include.
//
// Directional VPLs get no cube but an orthographic map instead: layer i of an RG32F 2D array
// holds, for batch[i], the distance along the direction of travel from the map's near plane
// (directional_frame.h) to the first surface.
//
// Meshes with masked or blended materials (glTF alphaMode MASK, BLEND) are not among the
// clusters: every cube face and orthographic map draws them whole from the scene's vertex buffer
// with an alpha-tested pipeline (shadow_masked.frag), which only scenes that draw such a
// material build. BLEND is hashed transparency with a seed per VPL, so that a blended surface
// shadows a fraction alpha of the VPLs behind it.
#include <cstdint>
#include <memory>
#include <span>

#include "engine/gpu/buffer.h"
#include "engine/gpu/graphics_pipeline.h"
#include "engine/gpu/image.h"
#include "engine/light/vpl.h"
#include "engine/render/kept_shadow_maps.h"
#include "engine/render/scene_geometry.h"
#include "engine/render/shadow_clusters.h"
#include "shaders/shared/shadow_map.h"

namespace mvpl::gpu {
class CommandList;
class Context;
}  // namespace mvpl::gpu

namespace mvpl::render {

class SceneGeometry;

using shared::kShadowNoOccluder;

// resolution: the side of a cube face in texels; max_batch: cubes in the array.
struct ShadowPassOptions {
    uint32_t resolution = 256;
    uint32_t max_batch = 32;
    // Whether a face draws only the clusters it can see (shadow_clusters.h) or every triangle.
    bool culling = true;
    // Surface VPLs (path length ≥ 1) draw the large meshes' simplified levels (the shadow proxy)
    // where `lod` allows them; false: their full triangles.
    bool proxy = true;
    // Each VPL draws each large mesh at the coarsest level whose error stays below
    // kLodFootprint of a texel's footprint at the mesh's distance (shadow_clusters.h); false:
    // level 0.
    bool lod = true;
    // Large meshes that bound a solid (closed_surface.h) draw only their faces towards a VPL
    // outside their box (the rasteriser culls the rest): the nearest surface along every ray
    // from outside a solid is one of its front faces. false: both faces of everything.
    bool front_faces = true;
    // Area and Surface VPLs draw only the texels of each face that their lit hemisphere can
    // reach (hemicube.h); false: every face that is not wholly behind them, in full.
    bool hemicube = true;
    // Device memory for cubes and orthographic maps kept beyond their batch and copied back when
    // the same VPL comes again (kept_shadow_maps.h); 0: none kept.
    uint64_t kept_bytes = 0;

    bool operator==(const ShadowPassOptions&) const = default;
};

class ShadowPass {
public:
    // shaders/shared/shadow_map.h: the depth a simplified mesh may move the surface by.
    static inline const float kLodFootprint = shared::kLodFootprint;

    ShadowPass(gpu::Context& context, const SceneGeometry& geometry, const ShadowClusters& clusters,
               const ShadowPassOptions& options);
    ~ShadowPass();
    ShadowPass(const ShadowPass&) = delete;
    ShadowPass& operator=(const ShadowPass&) = delete;

    // Renders the cubes (and the orthographic maps of directional VPLs) of batch, at most
    // max_batch VPLs, into cubes() and ortho_maps(); VPL i's only when skip is empty or
    // skip[i] is false (a VPL the shading pass never looks up: vpl_culling.h). With kept_bytes,
    // a kept map is copied instead of drawn, and the maps drawn are kept where they fit.
    void record(gpu::CommandList& cmd, std::span<const light::Vpl> batch,
                const std::vector<bool>& skip = {});
    // A new estimate begins (VplRenderer::begin): the kept cubes' eviction order.
    void new_estimate() {
        if (m_kept_cubes) m_kept_cubes->new_estimate();
        if (m_kept_ortho) m_kept_ortho->new_estimate();
    }
    // Before recording `batch`: the pools of kept maps it may fill.
    void reserve_kept(std::span<const light::Vpl> batch) {
        if (m_kept_cubes) m_kept_cubes->reserve(batch);
        if (m_kept_ortho) m_kept_ortho->reserve(batch);
    }
    KeptMapStats kept() const;

    const gpu::Image& cubes() const { return m_cubes; }
    // Orthographic maps of the directional VPLs (layer = index in the batch; at least 2 layers,
    // so that the view is always a 2D array).
    const gpu::Image& ortho_maps() const { return m_ortho; }
    const ShadowPassOptions& options() const { return m_options; }
    uint32_t resolution() const { return m_cubes.width(); }
    uint32_t max_batch() const { return m_cubes.layers() / 6; }
    // Surfaces closer than this to a VPL do not shadow (the near plane), relative to the scene.
    float near_distance() const { return m_near; }
    // Triangles drawn into cube faces and orthographic maps since construction (bench reports
    // the culling's effect).
    uint64_t triangles_drawn() const { return m_triangles_drawn; }
    // Of those, the triangles of solids drawn with their back faces culled (front_faces).
    uint64_t front_only_triangles() const { return m_front_only_triangles; }
    // Cube-face texels cleared and drawn since construction (the hemicubes' effect).
    uint64_t texels_drawn() const { return m_texels_drawn; }

private:
    void record_maps(gpu::CommandList& cmd, std::span<const light::Vpl> batch,
                     const std::vector<bool>& skip);
    void record_directional(gpu::CommandList& cmd, const light::Vpl& vpl, uint32_t layer);

    // Draws m_ranges: the full levels' with `simplified` (a member of push) 0, the simplified
    // levels' with 1 (shadow.frag marks their texels); solids seen from outside with front_faces.
    template <typename Push, typename Flag>
    void draw_casters(gpu::CommandList& cmd, const gpu::GraphicsPipeline& both_faces,
                      const gpu::GraphicsPipeline& front_faces, Push& push, Flag& simplified);
    // The level of detail vpl draws with faces of side `res`.
    LodChoice lod_choice(const light::Vpl& vpl, uint32_t res) const;

    const SceneGeometry* m_geometry;
    const ShadowClusters* m_clusters;
    ShadowPassOptions m_options;
    // The shadow casters on the GPU, every level.
    gpu::Buffer m_positions;
    gpu::Buffer m_indices;
    CasterRanges m_ranges;  // scratch, per face
    uint64_t m_triangles_drawn = 0;
    uint64_t m_front_only_triangles = 0;
    uint64_t m_texels_drawn = 0;
    gpu::Image m_cubes;
    gpu::Image m_depth;  // six layers, reused by every cube
    gpu::Image m_ortho;
    gpu::Image m_ortho_depth;
    std::unique_ptr<gpu::GraphicsPipeline> m_pipeline;
    std::unique_ptr<gpu::GraphicsPipeline> m_ortho_pipeline;
    // The same, culling back faces: for solids seen from outside (front_faces).
    std::unique_ptr<gpu::GraphicsPipeline> m_front_pipeline;
    std::unique_ptr<gpu::GraphicsPipeline> m_ortho_front_pipeline;
    // Masked scenes only: the draws of masked materials, their pipelines and textures.
    void draw_masked(gpu::CommandList& cmd, const gpu::GraphicsPipeline& pipeline,
                     VkDescriptorSet set, std::span<const std::byte> push, size_t material_offset,
                     bool floats);
    std::vector<GeometryDraw> m_masked_draws;
    std::unique_ptr<gpu::GraphicsPipeline> m_masked_pipeline;
    std::unique_ptr<gpu::GraphicsPipeline> m_masked_ortho_pipeline;
    std::vector<gpu::Image> m_masked_textures;
    VkDescriptorSet m_masked_set = nullptr;  // this recording's, per pipeline
    VkDescriptorSet m_masked_ortho_set = nullptr;
    // With kept_bytes: the cubes' and the orthographic maps' (kept_shadow_maps.h).
    std::unique_ptr<KeptShadowMaps> m_kept_cubes;
    std::unique_ptr<KeptShadowMaps> m_kept_ortho;
    uint32_t m_vpl_seed = 0;  // VPLs recorded so far: the seed of glTF BLEND's hash
    float m_near = 0.0f;
};

}  // namespace mvpl::render
