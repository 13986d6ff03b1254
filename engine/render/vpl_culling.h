#pragma once
// Per-batch culling of VPLs that cannot reach any visible point (issue 14, "shade fewer
// pairs"). The scene's triangles, every mesh's, are cut into chunks of consecutive triangles with
// bounding spheres; for a view, the chunks whose sphere meets the camera's frustum hold every
// point any pixel can see, at any sub-pixel position. An Area or Surface VPL lights only its
// front half-space (the factor max(0, n·ω)): when every such chunk lies behind its plane, its
// contribution to every visible receiver is exactly zero, and the renderer neither draws its
// shadow cube nor shades it — the image stays the same to the bit (tests/render/test_vpl_culling).
// Point, spot and directional VPLs are always kept. CPU only, Vulkan-free.
#include <cstdint>
#include <vector>

#include "engine/core/math.h"
#include "engine/light/vpl.h"
#include "engine/scene/scene.h"

namespace mvpl::render {

class VplCulling {
public:
    static constexpr uint32_t kChunkTriangles = 256;

    explicit VplCulling(const scene::Scene& scene);

    // Keeps the chunks that meet the frustum of `camera` for an image of width × height.
    void set_view(const scene::Camera& camera, uint32_t width, uint32_t height);
    // Whether `vpl` may light a point of the view (false only when it provably cannot).
    bool may_reach_view(const light::Vpl& vpl) const;

    size_t chunk_count() const { return m_chunks.size(); }
    size_t visible_chunk_count() const { return m_visible.size(); }

private:
    struct Box {
        Vec3 centre;
        Vec3 half;  // half extents, grown by the margin
        // The largest n·(x − p) over the box's points x.
        float support(const Vec3& n, const Vec3& p) const {
            return glm::dot(n, centre - p) + glm::dot(glm::abs(n), half);
        }
    };
    std::vector<Box> m_chunks;   // every chunk
    std::vector<Box> m_visible;  // those in the view
    float m_margin = 0.0f;       // for rounding: 1e-5 of the scene's diagonal
};

}  // namespace mvpl::render
