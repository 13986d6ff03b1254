#include "engine/render/g_buffer_pass.h"

#include <algorithm>
#include <array>
#include <bit>
#include <span>

#include "engine/gpu/buffer.h"
#include "engine/gpu/command_list.h"
#include "engine/gpu/compute_pipeline.h"
#include "engine/gpu/graphics_pipeline.h"
#include "engine/gpu/rendering.h"
#include "engine/gpu/shader_compiler.h"
#include "engine/render/scene_geometry.h"
#include "engine/render/shader_program.h"
#include "shaders/shared/push_constants.h"

namespace mvpl::render {
namespace {

using shared::GBufferPush;
using shared::MaterialPush;

gpu::GraphicsLayout g_buffer_layout(size_t textures) {
    gpu::GraphicsLayout layout;
    layout.vertex_stride = sizeof(GeometryVertex);
    layout.attributes = {{gpu::VertexFormat::float3, offsetof(GeometryVertex, position)},
                         {gpu::VertexFormat::float3, offsetof(GeometryVertex, normal)},
                         {gpu::VertexFormat::float3, offsetof(GeometryVertex, face_normal)},
                         {gpu::VertexFormat::float4, offsetof(GeometryVertex, uv)},
                         {gpu::VertexFormat::float4, offsetof(GeometryVertex, tangent)},
                         {gpu::VertexFormat::float4, offsetof(GeometryVertex, color)}};
    layout.color_formats.assign(kGBufferLayerCount, gpu::Format::rgba32_float);
    layout.depth = true;
    layout.push_constant_bytes = sizeof(GBufferPush);
    layout.bindings.assign(textures, gpu::BindingType::sampled_image);
    layout.dynamic_cull = true;
    return layout;
}

std::vector<uint32_t> compile_stage(const StageSource& stage, const gpu::SpirvCacheOptions& cache) {
    return gpu::compile_glsl_cached(gpu::stage_from_name(stage.name), stage.source,
                                    "render/" + stage.name, cache);
}

std::unique_ptr<gpu::GraphicsPipeline> make_pipeline(gpu::Context& context,
                                                     const SceneGeometry& geometry,
                                                     const StageSource* vert,
                                                     const StageSource* frag,
                                                     const gpu::SpirvCacheOptions& cache) {
    GBufferSources generated =
        generate_g_buffer_sources(geometry.graphs(), geometry.textures(), geometry.drawn());
    if (!vert || !frag) {
        vert = &generated.vert;
        frag = &generated.frag;
    }
    return std::make_unique<gpu::GraphicsPipeline>(
        context, compile_stage(*vert, cache), compile_stage(*frag, cache),
        g_buffer_layout(generated.fragment_textures.size()), "g-buffer");
}

// The textures `indices` of `textures` as sampled images, through one upload buffer that fits the
// largest (Image::upload): SpecGlossVsMetalRough's seven 2048² textures uploaded 4.6× faster on
// lavapipe than through a buffer each (perf samples of `mvpl render` at 48², 16 VPLs).
std::vector<gpu::Image> upload_textures(gpu::Context& context,
                                        const std::vector<scene::Texture>& textures,
                                        const std::vector<int>& indices) {
    uint64_t largest = 0;
    for (const int index : indices)
        largest = std::max<uint64_t>(largest, textures[size_t(index)].texels.size() * sizeof(Vec4));
    std::vector<gpu::Image> images;
    if (indices.empty()) return images;
    gpu::Buffer staging(context, largest, gpu::BufferUsage::none, gpu::MemoryLocation::upload,
                        "texture upload");
    for (const int index : indices) {
        const scene::Texture& t = textures[size_t(index)];
        images.emplace_back(
            context,
            gpu::ImageDesc{uint32_t(t.width), uint32_t(t.height), 1, gpu::Format::rgba32_float,
                           gpu::ImageUsage::sampled, false},
            "texture " + t.name);
        images.back().upload(std::as_bytes(std::span(t.texels)), staging);
    }
    return images;
}

// Whether the camera and its near plane's window lie outside the box of draw: its clipping then
// cannot open the solid to a view of its inside.
bool outside(const scene::Camera& camera, float aspect, const GeometryDraw& draw) {
    const Vec3 eye(camera.camera_to_world[3]);
    const float tan_half = std::tan(0.5f * camera.yfov);
    const float znear = camera.znear > 0.0f ? camera.znear : 1e-4f;
    // The near window's corners, as far from the eye as camera_view_projection puts them.
    const float reach = znear * std::sqrt(1.0f + tan_half * tan_half * (1.0f + aspect * aspect));
    return glm::any(glm::lessThan(eye, draw.lo - reach)) ||
           glm::any(glm::greaterThan(eye, draw.hi + reach));
}

}  // namespace

Mat4 camera_view_projection(const scene::Camera& camera, uint32_t width, uint32_t height,
                            Vec2 subpixel) {
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
    // The film point x + s must land on the pixel centre x + ½: a shift by (½ − s) pixels, 2/size
    // in NDC per pixel, applied in clip space as x' = x + shift · w (Vulkan's y runs down the
    // image as the film's does).
    Mat4 shift(1.0f);
    shift[3][0] = 2.0f * (0.5f - subpixel.x) / float(width);
    shift[3][1] = 2.0f * (0.5f - subpixel.y) / float(height);
    return shift * projection * glm::inverse(camera.camera_to_world);
}

GBufferPass::GBufferPass(gpu::Context& context, const SceneGeometry& geometry, uint32_t width,
                         uint32_t height, const StageSource* vert, const StageSource* frag,
                         const gpu::SpirvCacheOptions& cache)
    : m_geometry(&geometry),
      m_image(context,
              {width, height, kGBufferLayerCount, gpu::Format::rgba32_float,
               gpu::ImageUsage::color_attachment | gpu::ImageUsage::storage, false},
              "g-buffer"),
      m_depth(context,
              {width, height, 1, gpu::Format::d32_float, gpu::ImageUsage::depth_attachment, false},
              "g-buffer depth"),
      m_pipeline(make_pipeline(context, geometry, vert, frag, cache)) {
    const GBufferSources sources =
        generate_g_buffer_sources(geometry.graphs(), geometry.textures(), geometry.drawn());
    m_fragment_textures = upload_textures(context, geometry.textures(), sources.fragment_textures);
    if (!sources.has_material_pass()) return;
    gpu::ComputeLayout layout{{gpu::BindingType::storage_image}, sizeof(MaterialPush)};
    m_textures = upload_textures(context, geometry.textures(), sources.textures);
    layout.bindings.resize(layout.bindings.size() + m_textures.size(),
                           gpu::BindingType::sampled_image);
    m_material_pipeline = std::make_unique<gpu::ComputePipeline>(
        context,
        gpu::compile_glsl_cached(gpu::ShaderStage::compute, sources.material.source,
                                 "render/material.comp", cache),
        layout, "material pass");
}

GBufferPass::~GBufferPass() = default;

void GBufferPass::record(gpu::CommandList& cmd, const scene::Camera& camera, Vec2 subpixel,
                         bool cull_solids) {
    std::array<gpu::ColorTarget, kGBufferLayerCount> colors;
    for (uint32_t i = 0; i < kGBufferLayerCount; ++i)
        colors[i] = {&m_image, i, {0.0f, 0.0f, 0.0f, 0.0f}};
    const gpu::DepthTarget depth{&m_depth, 0, 0.0f};
    gpu::begin_rendering(cmd, colors, &depth);
    if (!m_fragment_textures.empty()) {
        std::vector<const gpu::Image*> images;
        for (const gpu::Image& t : m_fragment_textures)
            images.push_back(&t);
        gpu::bind_images(cmd, *m_pipeline, images);
    }
    GBufferPush push{};
    // glTF BLEND's hashed transparency: a pattern per sub-pixel position, so that the batches
    // of a jittered render average it into transparency (and a render is deterministic).
    const uint32_t seed = std::bit_cast<uint32_t>(subpixel.x) * 0x9E3779B9u ^
                          std::bit_cast<uint32_t>(subpixel.y) * 0x85EBCA6Bu;
    const Mat4 view_proj = camera_view_projection(camera, width(), height(), subpixel);
    std::copy_n(&view_proj[0][0], 16, push.view_proj);
    for (const GeometryDraw& draw : m_geometry->draws()) {
        const GeometryMaterial& m = m_geometry->materials()[draw.material];
        push.material_flags = m.double_sided ? 1u : 0u;
        push.seed = seed;
        push.material = draw.material;
        // One-sided materials: the rasteriser drops the back faces that the fragment stage would
        // discard (the same gl_FrontFacing), before their setup, which is most of a heavy
        // scene's G-buffer on lavapipe. Solids seen from outside hide their back faces behind
        // their front faces, double-sided or not (MetalRoughSpheresNoTextures' double-sided
        // spheres: −36 %).
        const bool cull =
            !m.double_sided ||
            (cull_solids && draw.solid && outside(camera, float(width()) / float(height()), draw));
        gpu::set_cull_back(cmd, *m_pipeline, cull);
        if (cull) m_front_only_triangles += draw.index_count / 3;
        const gpu::IndexRange range{draw.first_index, draw.index_count};
        gpu::draw_indexed(cmd, *m_pipeline, m_geometry->vertices(), m_geometry->indices(),
                          gpu::push_bytes(push), std::span(&range, 1));
    }
    gpu::end_rendering(cmd);
    if (m_material_pipeline) {
        cmd.barrier();
        std::vector<gpu::Resource> resources{&m_image};
        for (const gpu::Image& t : m_textures)
            resources.push_back(&t);
        const MaterialPush push{width(), height()};
        cmd.dispatch(*m_material_pipeline, resources, gpu::push_bytes(push), (width() + 7) / 8,
                     (height() + 7) / 8);
    }
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
        t.material = t.covered ? uint32_t(p[3] + 0.5f) - 1u : 0u;
        t.position = Vec3(p[0], p[1], p[2]);
        t.shading_normal = Vec3(ns[0], ns[1], ns[2]);
        const uint32_t flags = uint32_t(ns[3]);
        t.front_face = (flags & 1u) != 0;
        t.double_sided = (flags & 2u) != 0;
        t.closure_type = flags >> 2u;
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
