#include "engine/render/shadow_pass.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <optional>

#include "engine/gpu/command_list.h"
#include "engine/gpu/embedded_shaders.h"
#include "engine/gpu/gpu_error.h"
#include "engine/gpu/graphics_pipeline.h"
#include "engine/gpu/rendering.h"
#include "engine/gpu/shader_compiler.h"
#include "engine/gpu/spirv_cache.h"
#include "engine/render/directional_frame.h"
#include "engine/render/hemicube.h"
#include "engine/render/scene_geometry.h"
#include "engine/render/shader_program.h"
#include "engine/render/shadow_texel.h"
#include "shaders/shared/push_constants.h"

namespace mvpl::render {
namespace {

using shared::OrthoPush;
using shared::ShadowPush;

// The near plane as a fraction of the scene diagonal: scale-free, and small enough that only
// the surface a VPL lies on (distance 0) falls in front of it in practice.
constexpr float kNearFraction = 1e-5f;

// Whether every direction through cube face `face` lies strictly below the plane of normal n, so
// that an Area or Surface VPL (whose factor max(0, n·ω) is then 0) never looks the face up: the
// "hemicube" of docs/design.md, one face fewer for axis-aligned normals. n·ω is linear over the
// face before normalisation, so its maximum is at a corner; the margin keeps the shader's rounded
// n·ω from reaching 0 on the face.
bool face_behind(const Vec3& n, uint32_t face) {
    const int axis = int(face / 2);
    Vec3 a(0.0f);
    a[axis] = face % 2 == 0 ? 1.0f : -1.0f;
    Vec3 u(0.0f);
    Vec3 v(0.0f);
    u[(axis + 1) % 3] = 1.0f;
    v[(axis + 2) % 3] = 1.0f;
    for (const float su : {-1.0f, 1.0f}) {
        for (const float sv : {-1.0f, 1.0f}) {
            if (glm::dot(n, a + su * u + sv * v) > -1e-3f) return false;
        }
    }
    return true;
}

// front_clockwise: the cull-back variant for solids; a face turned towards the VPL winds clockwise
// in a cube face's framebuffer (the map to (s_c, t_c, m_a) has determinant −1 on every face) and
// counter-clockwise in an orthographic map's (u × v = the direction of travel: Frame's basis).
gpu::GraphicsLayout shadow_layout(uint32_t push_constant_bytes,
                                  std::optional<bool> front_clockwise = std::nullopt) {
    gpu::GraphicsLayout layout;
    layout.cull_back = front_clockwise.has_value();
    layout.front_clockwise = front_clockwise.value_or(false);
    layout.vertex_stride = sizeof(Vec3);
    layout.attributes = {{gpu::VertexFormat::float3, 0}};
    layout.color_formats = {kShadowTexelFormat};
    layout.depth = true;
    layout.push_constant_bytes = push_constant_bytes;
    return layout;
}

// The alpha-tested pipelines' vertices: the G-buffer's (position, uv, COLOR_0 at locations 0-2).
gpu::GraphicsLayout masked_layout(uint32_t push_constant_bytes, size_t textures) {
    gpu::GraphicsLayout layout = shadow_layout(push_constant_bytes);
    layout.vertex_stride = sizeof(GeometryVertex);
    layout.attributes = {{gpu::VertexFormat::float3, offsetof(GeometryVertex, position)},
                         {gpu::VertexFormat::float4, offsetof(GeometryVertex, uv)},
                         {gpu::VertexFormat::float4, offsetof(GeometryVertex, color)}};
    layout.bindings.assign(textures, gpu::BindingType::sampled_image);
    return layout;
}

// An embedded vertex stage with MVPL_MASKED defined (after its #version line).
std::vector<uint32_t> compile_masked_vertex(const std::string& name) {
    std::string text(gpu::embedded_shader(name));
    const size_t eol = text.find('\n');
    text.insert(eol + 1, "#define MVPL_MASKED\n");
    const std::string source = expand_template(text, {}, {});
    return gpu::compile_glsl_cached(gpu::ShaderStage::vertex, source, name + " (masked)", {});
}

template <typename T>
gpu::Buffer upload_buffer(gpu::Context& context, const std::vector<T>& data, gpu::BufferUsage usage,
                          const std::string& name) {
    gpu::Buffer buffer(context, std::max<uint64_t>(data.size() * sizeof(T), sizeof(T)), usage,
                       gpu::MemoryLocation::device, name);
    if (!data.empty()) buffer.upload(std::as_bytes(std::span(data)));
    return buffer;
}

}  // namespace

ShadowPass::ShadowPass(gpu::Context& context, const SceneGeometry& geometry,
                       const ShadowClusters& clusters, const ShadowPassOptions& options)
    : m_geometry(&geometry),
      m_clusters(&clusters),
      m_options(options),
      m_positions(upload_buffer(context, clusters.positions(), gpu::BufferUsage::vertex,
                                "shadow caster positions")),
      m_indices(upload_buffer(context, clusters.indices(), gpu::BufferUsage::index,
                              "shadow caster indices")),
      m_cubes(context,
              {options.resolution, options.resolution, 6 * options.max_batch, kShadowTexelFormat,
               gpu::ImageUsage::color_attachment | gpu::ImageUsage::storage, false},
              "shadow cubes"),
      m_depth(context,
              {options.resolution, options.resolution, 6, gpu::Format::d32_float,
               gpu::ImageUsage::depth_attachment, false},
              "shadow depth"),
      m_ortho(
          context,
          {options.resolution, options.resolution, std::max(options.max_batch, 2u),
           kShadowTexelFormat, gpu::ImageUsage::color_attachment | gpu::ImageUsage::sampled, false},
          "directional shadow maps"),
      m_ortho_depth(context,
                    {options.resolution, options.resolution, 1, gpu::Format::d32_float,
                     gpu::ImageUsage::depth_attachment, false},
                    "directional shadow depth"),
      m_pipeline(std::make_unique<gpu::GraphicsPipeline>(
          context, gpu::compile_embedded_shader("render/shadow.vert"),
          gpu::compile_embedded_shader("render/shadow.frag"), shadow_layout(sizeof(ShadowPush)),
          "shadow")),
      m_ortho_pipeline(std::make_unique<gpu::GraphicsPipeline>(
          context, gpu::compile_embedded_shader("render/shadow_ortho.vert"),
          gpu::compile_embedded_shader("render/shadow.frag"), shadow_layout(sizeof(OrthoPush)),
          "directional shadow")),
      m_front_pipeline(std::make_unique<gpu::GraphicsPipeline>(
          context, gpu::compile_embedded_shader("render/shadow.vert"),
          gpu::compile_embedded_shader("render/shadow.frag"),
          shadow_layout(sizeof(ShadowPush), true), "shadow (front faces)")),
      m_ortho_front_pipeline(std::make_unique<gpu::GraphicsPipeline>(
          context, gpu::compile_embedded_shader("render/shadow_ortho.vert"),
          gpu::compile_embedded_shader("render/shadow.frag"),
          shadow_layout(sizeof(OrthoPush), false), "directional shadow (front faces)")),
      m_near(kNearFraction * std::max(geometry.bounds().diagonal(), 1e-30f)) {
    if (options.kept_bytes > 0) {
        // The budget in proportion to a map's layers: as many orthographic maps as cubes.
        const uint64_t ortho_bytes = options.kept_bytes / 7;
        m_kept_cubes =
            std::make_unique<KeptShadowMaps>(context, false, options.resolution, options.max_batch,
                                             options.kept_bytes - ortho_bytes);
        m_kept_ortho = std::make_unique<KeptShadowMaps>(context, true, options.resolution,
                                                        options.max_batch, ortho_bytes);
    }
    std::vector<bool> masked(geometry.graphs().size(), false);
    for (size_t i = 0; i < masked.size(); ++i)
        masked[i] = geometry.graphs()[i].alpha_tested();
    for (const GeometryDraw& draw : geometry.draws()) {
        if (draw.material < masked.size() && masked[draw.material]) m_masked_draws.push_back(draw);
    }
    if (m_masked_draws.empty()) return;
    const ShadowAlphaSources code =
        generate_shadow_alpha_sources(geometry.graphs(), geometry.textures(), geometry.drawn());
    const std::vector<uint32_t> frag_spirv = gpu::compile_glsl_cached(
        gpu::ShaderStage::fragment, code.frag.source, "render/" + code.frag.name, {});
    for (const int index : code.textures) {
        const scene::Texture& t = geometry.textures()[size_t(index)];
        gpu::Image image(context,
                         {uint32_t(t.width), uint32_t(t.height), 1, gpu::Format::rgba32_float,
                          gpu::ImageUsage::sampled, false},
                         "texture " + t.name);
        image.upload(t.texels);
        m_masked_textures.push_back(std::move(image));
    }
    m_masked_pipeline = std::make_unique<gpu::GraphicsPipeline>(
        context, compile_masked_vertex("render/shadow.vert"), frag_spirv,
        masked_layout(sizeof(ShadowPush), code.textures.size()), "masked shadow");
    m_masked_ortho_pipeline = std::make_unique<gpu::GraphicsPipeline>(
        context, compile_masked_vertex("render/shadow_ortho.vert"), frag_spirv,
        masked_layout(sizeof(OrthoPush), code.textures.size()), "masked directional shadow");
}

void ShadowPass::draw_masked(gpu::CommandList& cmd, const gpu::GraphicsPipeline& pipeline,
                             VkDescriptorSet set, std::span<const std::byte> push,
                             size_t material_offset, bool floats) {
    gpu::bind_image_set(cmd, pipeline, set);
    // The push constants with the draw's material at material_offset and the VPL's seed after
    // it: uints for cube faces, floats for orthographic maps (exact below 2^24).
    std::vector<std::byte> bytes(push.begin(), push.end());
    const uint32_t seed = m_vpl_seed % (1u << 24);
    for (const GeometryDraw& draw : m_masked_draws) {
        if (floats) {
            const float values[2] = {float(draw.material), float(seed)};
            std::memcpy(bytes.data() + material_offset, values, sizeof(values));
        } else {
            const uint32_t values[2] = {draw.material, seed};
            std::memcpy(bytes.data() + material_offset, values, sizeof(values));
        }
        const gpu::IndexRange range{draw.first_index, draw.index_count};
        gpu::draw_indexed(cmd, pipeline, m_geometry->vertices(), m_geometry->indices(), bytes,
                          std::span(&range, 1));
        m_triangles_drawn += draw.index_count / 3;
    }
}

ShadowPass::~ShadowPass() = default;

template <typename Push, typename Flag>
void ShadowPass::draw_casters(gpu::CommandList& cmd, const gpu::GraphicsPipeline& both_faces,
                              const gpu::GraphicsPipeline& front_faces, Push& push,
                              Flag& simplified) {
    for (size_t kind = 0; kind < m_ranges.by_kind.size(); ++kind) {
        const std::vector<gpu::IndexRange>& ranges = m_ranges.by_kind[kind];
        if (ranges.empty()) continue;
        const bool front_only = (kind & CasterRanges::kFrontOnly) != 0 && m_options.front_faces;
        for (const gpu::IndexRange& r : ranges) {
            m_triangles_drawn += r.index_count / 3;
            if (front_only) m_front_only_triangles += r.index_count / 3;
        }
        simplified = Flag((kind & CasterRanges::kSimplified) != 0 ? 1 : 0);
        gpu::draw_indexed(cmd, front_only ? front_faces : both_faces, m_positions, m_indices,
                          gpu::push_bytes(push), ranges);
    }
    // The masked draws that may follow are never simplified.
    simplified = Flag(0);
}

LodChoice ShadowPass::lod_choice(const light::Vpl& vpl, uint32_t res) const {
    LodChoice lod;
    // A face's texel spans at most 2 / res radians, at its centre. No VPL draws a simplified level
    // nearer than that rule allows: a coarser copy of the surface a VPL lies on stands in front
    // of it and hides everything else (a surface VPL drawing the proxy at any distance lost every
    // bounce after the first inside a closed sphere: tests/render/test_closed_interiors.cpp).
    const bool simplified = m_options.lod && (m_options.proxy || vpl.path_length == 0);
    if (simplified) lod.error_per_distance = kLodFootprint * 2.0f / float(res);
    return lod;
}

void ShadowPass::record(gpu::CommandList& cmd, std::span<const light::Vpl> batch,
                        const std::vector<bool>& skip) {
    if (batch.size() > max_batch()) {
        throw gpu::GpuError("shadow pass: a batch of " + std::to_string(batch.size()) +
                            " VPLs for " + std::to_string(max_batch()) + " cubes");
    }
    if (!m_kept_cubes) {
        record_maps(cmd, batch, skip);
        return;
    }
    // The previous batch's shading has read the maps (accumulate() waits for each batch).
    const std::vector<bool> cubes = m_kept_cubes->restore(cmd, batch, skip, m_cubes);
    const std::vector<bool> ortho = m_kept_ortho->restore(cmd, batch, skip, m_ortho);
    std::vector<bool> draw_skip(batch.size()), drawn(batch.size());
    for (size_t i = 0; i < batch.size(); ++i) {
        draw_skip[i] = cubes[i] || ortho[i] || (!skip.empty() && skip[i]);
        drawn[i] = !draw_skip[i];
    }
    record_maps(cmd, batch, draw_skip);
    cmd.barrier();
    m_kept_cubes->keep(cmd, batch, drawn, m_cubes);
    m_kept_ortho->keep(cmd, batch, drawn, m_ortho);
}

KeptMapStats ShadowPass::kept() const {
    KeptMapStats stats;
    for (const KeptShadowMaps* kept : {m_kept_cubes.get(), m_kept_ortho.get()}) {
        if (!kept) continue;
        stats.maps += kept->size();
        stats.capacity += kept->capacity();
        stats.budget_bytes += kept->budget_bytes();
        stats.restored += kept->restored();
    }
    return stats;
}

void ShadowPass::record_maps(gpu::CommandList& cmd, std::span<const light::Vpl> batch,
                             const std::vector<bool>& skip) {
    bool depth_in_use = false;
    bool ortho_depth_in_use = false;
    if (m_masked_pipeline) {
        // Written once per recording, bound again before each face's masked draws.
        std::vector<const gpu::Image*> images;
        for (const gpu::Image& t : m_masked_textures)
            images.push_back(&t);
        m_masked_set = gpu::write_image_set(cmd, *m_masked_pipeline, images);
        m_masked_ortho_set = gpu::write_image_set(cmd, *m_masked_ortho_pipeline, images);
    }
    for (uint32_t i = 0; i < batch.size(); ++i) {
        const light::Vpl& vpl = batch[i];
        ++m_vpl_seed;  // each VPL its own hashed-transparency pattern (glTF BLEND)
        if (!skip.empty() && skip[i]) continue;
        if (vpl.type == light::VplType::Directional) {
            if (ortho_depth_in_use) cmd.barrier();
            ortho_depth_in_use = true;
            record_directional(cmd, vpl, i);
            continue;
        }
        // The six depth layers are reused by every cube: the previous cube's depth tests must be
        // done before this cube's clears.
        if (depth_in_use) cmd.barrier();
        depth_in_use = true;
        const bool hemisphere =
            vpl.type == light::VplType::Area || vpl.type == light::VplType::Surface;
        const uint32_t res = resolution();
        for (uint32_t face = 0; face < 6; ++face) {
            gpu::RenderArea area{0, 0, res, res};
            if (hemisphere && m_options.hemicube) {
                const std::optional<FaceRect> rect = lit_face_rect(vpl.normal, face, res);
                if (!rect) continue;
                area = {rect->x, rect->y, rect->width, rect->height};
            } else if (hemisphere && face_behind(vpl.normal, face)) {
                continue;
            }
            m_texels_drawn += uint64_t(area.width) * area.height;
            const gpu::ColorTarget color{
                &m_cubes, 6 * i + face, {kShadowNoOccluder, 0.0f, 0.0f, 0.0f}};
            const gpu::DepthTarget depth{&m_depth, face, 0.0f};
            gpu::begin_rendering(cmd, std::span(&color, 1), &depth, &area);
            ShadowPush push{{vpl.position.x, vpl.position.y, vpl.position.z, m_near},
                            {face, 0u, 0u, 0u}};
            // Materials do not matter for distances: one index buffer for the whole scene, of
            // which the face draws the clusters it can see at their levels.
            const LodChoice lod = lod_choice(vpl, res);
            if (m_options.culling) {
                // A face's texel spans at most 2/resolution radians.
                m_clusters->visible_ranges(vpl.position, face, hemisphere ? &vpl.normal : nullptr,
                                           2.0f / float(res), lod, m_ranges);
            } else {
                m_clusters->level_ranges(vpl.position, lod, m_ranges);
            }
            draw_casters(cmd, *m_pipeline, *m_front_pipeline, push, push.face[3]);
            if (m_masked_pipeline) {
                draw_masked(cmd, *m_masked_pipeline, m_masked_set, gpu::push_bytes(push),
                            offsetof(ShadowPush, face) + sizeof(uint32_t), false);
            }
            gpu::end_rendering(cmd);
        }
    }
}

void ShadowPass::record_directional(gpu::CommandList& cmd, const light::Vpl& vpl, uint32_t layer) {
    const DirectionalFrame f = directional_frame(vpl.normal, m_geometry->bounds());
    const gpu::ColorTarget color{&m_ortho, layer, {kShadowNoOccluder, 0.0f, 0.0f, 0.0f}};
    const gpu::DepthTarget depth{&m_ortho_depth, 0, 0.0f};
    gpu::begin_rendering(cmd, std::span(&color, 1), &depth);
    OrthoPush push{{f.u.x, f.u.y, f.u.z, f.origin.x},
                   {f.v.x, f.v.y, f.v.z, f.origin.y},
                   {f.dir.x, f.dir.y, f.dir.z, f.origin.z},
                   {f.extent, f.depth, 0.0f, 0.0f}};
    // The map's texels are extent / resolution wide wherever a mesh stands.
    LodChoice lod;
    if (m_options.lod) lod.error_anywhere = kLodFootprint * f.extent / float(resolution());
    m_clusters->level_ranges(vpl.position, lod, m_ranges, true);
    draw_casters(cmd, *m_ortho_pipeline, *m_ortho_front_pipeline, push, push.extents[2]);
    if (m_masked_ortho_pipeline) {
        draw_masked(cmd, *m_masked_ortho_pipeline, m_masked_ortho_set, gpu::push_bytes(push),
                    offsetof(OrthoPush, extents) + 2 * sizeof(float), true);
    }
    gpu::end_rendering(cmd);
}

}  // namespace mvpl::render
