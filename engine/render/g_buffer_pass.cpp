#include "engine/render/g_buffer_pass.h"

#include <algorithm>
#include <array>

#include "engine/gpu/command_list.h"
#include "engine/gpu/graphics_pipeline.h"
#include "engine/gpu/shader_compiler.h"
#include "engine/render/scene_geometry.h"

namespace mvpl::render {
namespace {

// Mirrors GBufferPush in shaders/render/g_buffer_push.glsl.
struct GBufferPush {
    float view_proj[16];
    float base_color_metallic[4];
    float specular_color_specular[4];
    float emission_roughness[4];
    float ior;
    uint32_t material_flags;
};
static_assert(sizeof(GBufferPush) == 120);

gpu::GraphicsLayout g_buffer_layout() {
    gpu::GraphicsLayout layout;
    layout.vertex_stride = sizeof(GeometryVertex);
    layout.attributes = {{gpu::VertexFormat::float3, offsetof(GeometryVertex, position)},
                         {gpu::VertexFormat::float3, offsetof(GeometryVertex, normal)},
                         {gpu::VertexFormat::float3, offsetof(GeometryVertex, face_normal)}};
    layout.color_formats.assign(kGBufferLayerCount, gpu::Format::rgba32_float);
    layout.depth = true;
    layout.push_constant_bytes = sizeof(GBufferPush);
    return layout;
}

}  // namespace

Mat4 camera_view_projection(const scene::Camera& camera, uint32_t width, uint32_t height) {
    const float tan_half = std::tan(0.5f * camera.yfov);
    const float aspect = float(width) / float(height);
    const float znear = camera.znear > 0.0f ? camera.znear : 1e-4f;
    // View space: −Z forward, +Y up. Clip: x = x_v / (tan·aspect), y = −y_v / tan (Vulkan's y
    // points down the image), w = −z_v, z = znear, so z_ndc = znear / (−z_v) (reversed, infinite).
    Mat4 projection(0.0f);
    projection[0][0] = 1.0f / (tan_half * aspect);
    projection[1][1] = -1.0f / tan_half;
    projection[2][3] = -1.0f;
    projection[3][2] = znear;
    return projection * glm::inverse(camera.camera_to_world);
}

GBufferPass::GBufferPass(gpu::Context& context, const SceneGeometry& geometry, uint32_t width,
                         uint32_t height)
    : m_geometry(&geometry),
      m_image(context,
              {width, height, kGBufferLayerCount, gpu::Format::rgba32_float,
               gpu::ImageUsage::color_attachment | gpu::ImageUsage::storage, false},
              "g-buffer"),
      m_depth(context,
              {width, height, 1, gpu::Format::d32_float, gpu::ImageUsage::depth_attachment, false},
              "g-buffer depth"),
      m_pipeline(std::make_unique<gpu::GraphicsPipeline>(
          context, gpu::compile_embedded_shader("render/g_buffer.vert"),
          gpu::compile_embedded_shader("render/g_buffer.frag"), g_buffer_layout(), "g-buffer")) {}

GBufferPass::~GBufferPass() = default;

void GBufferPass::record(gpu::CommandList& cmd, const scene::Camera& camera) {
    std::array<gpu::ColorTarget, kGBufferLayerCount> colors;
    for (uint32_t i = 0; i < kGBufferLayerCount; ++i)
        colors[i] = {&m_image, i, {0.0f, 0.0f, 0.0f, 0.0f}};
    const gpu::DepthTarget depth{&m_depth, 0, 0.0f};
    gpu::begin_rendering(cmd, colors, &depth);
    GBufferPush push{};
    const Mat4 view_proj = camera_view_projection(camera, width(), height());
    std::copy_n(&view_proj[0][0], 16, push.view_proj);
    for (const GeometryDraw& draw : m_geometry->draws()) {
        const GeometryMaterial& m = m_geometry->materials()[draw.material];
        const material::ClosureParams& c = m.closure;
        push.base_color_metallic[0] = c.base_color.r;
        push.base_color_metallic[1] = c.base_color.g;
        push.base_color_metallic[2] = c.base_color.b;
        push.base_color_metallic[3] = c.metallic;
        push.specular_color_specular[0] = c.specular_color.r;
        push.specular_color_specular[1] = c.specular_color.g;
        push.specular_color_specular[2] = c.specular_color.b;
        push.specular_color_specular[3] = c.specular;
        push.emission_roughness[0] = m.emission.r;
        push.emission_roughness[1] = m.emission.g;
        push.emission_roughness[2] = m.emission.b;
        push.emission_roughness[3] = c.roughness;
        push.ior = c.ior;
        push.material_flags = m.double_sided ? 1u : 0u;
        gpu::draw(cmd, *m_pipeline, m_geometry->vertices(), gpu::push_bytes(push),
                  draw.first_vertex, draw.vertex_count);
    }
    gpu::end_rendering(cmd);
}

std::vector<GBufferTexel> GBufferPass::download() const {
    const std::vector<float> data = m_image.download_as<float>(0, kGBufferLayerCount);
    const size_t pixels = size_t(width()) * height();
    std::vector<GBufferTexel> texels(pixels);
    const auto at = [&](uint32_t layer, size_t i) { return &data[(layer * pixels + i) * 4]; };
    for (size_t i = 0; i < pixels; ++i) {
        GBufferTexel& t = texels[i];
        const float* p = at(kGBufferPosition, i);
        const float* ns = at(kGBufferShadingNormal, i);
        const float* ng = at(kGBufferGeometricNormal, i);
        const float* base = at(kGBufferBaseColor, i);
        const float* spec = at(kGBufferSpecular, i);
        const float* emission = at(kGBufferEmission, i);
        t.covered = p[3] > 0.0f;
        t.position = Vec3(p[0], p[1], p[2]);
        t.shading_normal = Vec3(ns[0], ns[1], ns[2]);
        const uint32_t flags = uint32_t(ns[3]);
        t.front_face = (flags & 1u) != 0;
        t.double_sided = (flags & 2u) != 0;
        t.geometric_normal = Vec3(ng[0], ng[1], ng[2]);
        t.closure.metallic = ng[3];
        t.closure.base_color = Rgb(base[0], base[1], base[2]);
        t.closure.roughness = base[3];
        t.closure.specular_color = Rgb(spec[0], spec[1], spec[2]);
        t.closure.specular = spec[3];
        t.emission = Rgb(emission[0], emission[1], emission[2]);
        t.closure.ior = emission[3];
    }
    return texels;
}

}  // namespace mvpl::render
