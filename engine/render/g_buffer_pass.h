#pragma once
// Pass 1 (docs/design.md, "GPU passes"): rasterises every scene triangle once per view with the
// scene camera into an RGBA32F 2D array, one layer per attribute, which the shading pass reads.
// Pixel (x, y) holds the first surface along scene::generate_camera_ray(camera, w, h,
// (x + s.x, y + s.y)), row 0 at the top, for the sub-pixel position s ∈ [0, 1)² of the recording
// (the pixel centre by default; engine/core/subpixel.h). Vulkan-free to include.
#include <cstdint>
#include <memory>
#include <vector>

#include "engine/core/color.h"
#include "engine/core/math.h"
#include "engine/gpu/image.h"
#include "engine/gpu/spirv_cache.h"
#include "engine/material/closure.h"
#include "engine/scene/scene.h"

namespace mvpl::gpu {
class CommandList;
class Context;
class ComputePipeline;
class GraphicsPipeline;
}  // namespace mvpl::gpu

namespace mvpl::render {

class SceneGeometry;
struct StageSource;

// Layers of the G-buffer array (see shaders/render/g_buffer.frag for the packing).
enum GBufferLayer : uint32_t {
    kGBufferPosition = 0,
    kGBufferShadingNormal = 1,
    kGBufferGeometricNormal = 2,
    kGBufferBaseColor = 3,
    kGBufferSpecular = 4,
    kGBufferEmission = 5,
    kGBufferUv = 6,       // uv0, uv1
    kGBufferTangent = 7,  // unit tangent ⟂ the interpolated normal, w = bitangent sign
    kGBufferLayerCount = 8,
};

// One pixel of the G-buffer, unpacked on the host (tests, debugging).
struct GBufferTexel {
    bool covered = false;
    uint32_t material = 0;  // scene material index
    Vec3 position{0.0f};
    Vec3 shading_normal{0.0f};    // interpolated vertex normal on the winding normal's side
    Vec3 geometric_normal{0.0f};  // the triangle's winding normal
    bool front_face = false;      // the camera sees the side the winding normal points to
    bool double_sided = false;
    material::ClosureParams closure;
    uint32_t closure_type = 0;  // material::ClosureType
    Rgb emission{0.0f};         // zero on back faces
};

// The camera's reversed infinite perspective in Vulkan clip space: x right, y down (row 0 at the
// top), z_ndc = znear / view depth. aspect = width / height, as generate_camera_ray. The image is
// shifted so that the rasteriser's sample at a pixel's centre sees the film point at `subpixel`
// inside that pixel.
Mat4 camera_view_projection(const scene::Camera& camera, uint32_t width, uint32_t height,
                            Vec2 subpixel = Vec2(0.5f));

class GBufferPass {
public:
    // vert/frag: the generated stages (shader_program.h); nullptr: generated here from the
    // geometry's material graphs.
    GBufferPass(gpu::Context& context, const SceneGeometry& geometry, uint32_t width,
                uint32_t height, const StageSource* vert = nullptr,
                const StageSource* frag = nullptr, const gpu::SpirvCacheOptions& cache = {});
    ~GBufferPass();
    GBufferPass(const GBufferPass&) = delete;
    GBufferPass& operator=(const GBufferPass&) = delete;

    // cull_solids: the back faces of solids (GeometryDraw::solid) are culled where the camera is
    // outside their box, as those of one-sided materials always are; the same image.
    void record(gpu::CommandList& cmd, const scene::Camera& camera, Vec2 subpixel = Vec2(0.5f),
                bool cull_solids = true);
    // Triangles drawn with their back faces culled since construction.
    uint64_t front_only_triangles() const { return m_front_only_triangles; }

    const gpu::Image& image() const { return m_image; }
    uint32_t width() const { return m_image.width(); }
    uint32_t height() const { return m_image.height(); }

    // Reads the G-buffer back (after the recording was submitted), row-major, row 0 at the top.
    std::vector<GBufferTexel> download() const;

private:
    const SceneGeometry* m_geometry;
    gpu::Image m_image;
    gpu::Image m_depth;
    std::unique_ptr<gpu::GraphicsPipeline> m_pipeline;
    // The material pass (shader_program.h, GBufferSources): only for graphs with image textures.
    std::unique_ptr<gpu::ComputePipeline> m_material_pipeline;
    std::vector<gpu::Image> m_textures;
    // The fragment stage's textures (GBufferSources::fragment_textures): masked scenes only.
    std::vector<gpu::Image> m_fragment_textures;
    uint64_t m_front_only_triangles = 0;
};

}  // namespace mvpl::render
