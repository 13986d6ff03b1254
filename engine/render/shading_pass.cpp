#include "engine/render/shading_pass.h"

#include <algorithm>
#include <cstring>

#include "engine/gpu/command_list.h"
#include "engine/gpu/compute_pipeline.h"
#include "engine/gpu/gpu_error.h"
#include "engine/gpu/shader_compiler.h"
#include "engine/gpu/spirv_cache.h"
#include "engine/render/gpu_vpl.h"
#include "engine/render/shadow_texel.h"
#include "shaders/shared/interleave.h"
#include "shaders/shared/push_constants.h"

namespace mvpl::render {
namespace {

using shared::kAddEmission;
using shared::kMaxShadingBatch;
using shared::kShadows;
using shared::ShadingPush;
constexpr uint32_t kShadingGroupSize = 8;

// Binding 3, the shadow cubes, is a storage image: the shader picks face and texel itself
// (shadow_lookup.glsl, cube_texel). Binding 4 (the directional maps) exists only in programs
// with directional VPLs or specular chains, binding 5 (the chain records) only in the latter.
gpu::ComputeLayout shading_layout(const ShaderFeatures& features) {
    gpu::ComputeLayout layout{{gpu::BindingType::storage_image, gpu::BindingType::storage_image,
                               gpu::BindingType::uniform_buffer, gpu::BindingType::storage_image},
                              sizeof(ShadingPush)};
    if (features.has_directional() || features.specular_chains)
        layout.bindings.push_back(gpu::BindingType::sampled_image);
    if (features.specular_chains) layout.bindings.push_back(gpu::BindingType::storage_buffer);
    return layout;
}

std::unique_ptr<gpu::ComputePipeline> make_pipeline(gpu::Context& context,
                                                    const ShaderFeatures& features,
                                                    const StageSource* source,
                                                    const gpu::SpirvCacheOptions& cache) {
    StageSource generated;
    if (!source) {
        generated = generate_shading_source(features);
        source = &generated;
    }
    return std::make_unique<gpu::ComputePipeline>(
        context,
        gpu::compile_glsl_cached(gpu::ShaderStage::compute, source->source,
                                 "render/" + source->name, cache),
        shading_layout(features), "shading");
}

}  // namespace

ShadingPass::ShadingPass(gpu::Context& context, uint32_t width, uint32_t height, uint32_t max_batch,
                         const ShaderFeatures& features, const StageSource* source,
                         const gpu::SpirvCacheOptions& cache)
    : m_context(&context),
      m_accumulation(context,
                     {width, height, 1, gpu::Format::rgba32_float, gpu::ImageUsage::storage, false},
                     "accumulation"),
      m_vpls(context, uint64_t(kMaxShadingBatch) * sizeof(GpuVpl), gpu::BufferUsage::uniform,
             gpu::MemoryLocation::upload, "vpl batch"),
      m_no_shadows(context, {1, 1, 6, kShadowTexelFormat, gpu::ImageUsage::storage, false},
                   "no shadows"),
      m_no_ortho_shadows(context, {1, 1, 2, kShadowTexelFormat, gpu::ImageUsage::sampled, false},
                         "no directional shadows"),
      m_features(features),
      m_cache(cache),
      m_pipeline(make_pipeline(context, features, source, cache)),
      m_max_batch(std::max(max_batch, 1u)) {
    if (m_max_batch > kMaxShadingBatch) {
        throw gpu::GpuError("shading pass: batches of at most " + std::to_string(kMaxShadingBatch) +
                            " VPLs");
    }
}

ShadingPass::~ShadingPass() = default;

void ShadingPass::upload(std::span<const light::Vpl> batch, const scene::Bounds& bounds) {
    if (batch.size() > m_max_batch) {
        throw gpu::GpuError("shading pass: a batch of " + std::to_string(batch.size()) +
                            " VPLs for room for " + std::to_string(m_max_batch));
    }
    const std::vector<GpuVpl> gpu_vpls = to_gpu_vpls(batch, bounds);
    ShaderFeatures needed = m_features;
    for (const GpuVpl& g : gpu_vpls) {
        if (g.type >= uint32_t(kVplTypeCount)) {
            throw gpu::GpuError("shading pass: VPL type " + std::to_string(g.type) + " is unknown");
        }
        needed.vpl_types[g.type] = true;
        if (g.type == uint32_t(light::VplType::Surface))
            needed.closure_types[g.closure_type] = true;
    }
    if (needed.vpl_types != m_features.vpl_types ||
        needed.closure_types != m_features.closure_types) {
        m_features = needed;
        m_pipeline = make_pipeline(*m_context, m_features, nullptr, m_cache);
    }
    if (!gpu_vpls.empty()) {
        std::memcpy(m_vpls.mapped(), gpu_vpls.data(), gpu_vpls.size() * sizeof(GpuVpl));
    }
    m_count = uint32_t(batch.size());
}

void ShadingPass::record_clear(gpu::CommandList& cmd) {
    cmd.clear_color(m_accumulation, {0.0f, 0.0f, 0.0f, 0.0f});
}

void ShadingPass::record(gpu::CommandList& cmd, const gpu::Image& g_buffer,
                         const ShadingBatch& batch) {
    const uint32_t width = m_accumulation.width();
    const uint32_t height = m_accumulation.height();
    if (g_buffer.width() != width || g_buffer.height() != height) {
        throw gpu::GpuError("shading pass: the G-buffer and the accumulation differ in size");
    }
    const gpu::Image* shadows = batch.shadows ? batch.shadows : &m_no_shadows;
    const gpu::Image* ortho = batch.ortho_shadows ? batch.ortho_shadows : &m_no_ortho_shadows;
    if (bool(batch.shadows) != bool(batch.ortho_shadows)) {
        throw gpu::GpuError("shading pass: cube and directional shadow maps come together");
    }
    if (batch.shadows && batch.shadows->layers() < 6 * m_count) {
        throw gpu::GpuError("shading pass: fewer shadow cubes than VPLs in the batch");
    }
    ShadingPush push{};
    push.camera_position[0] = batch.camera_position.x;
    push.camera_position[1] = batch.camera_position.y;
    push.camera_position[2] = batch.camera_position.z;
    push.d_min2 = batch.d_min * batch.d_min;
    push.vsl_r2 = batch.vsl_radius * batch.vsl_radius;
    push.texel_angle = 2.0f / float(shadows->width());
    push.vpl_count = m_count;
    push.flags = (batch.add_emission ? kAddEmission : 0u) | (batch.shadows ? kShadows : 0u);
    push.size[0] = width;
    push.size[1] = height;
    const uint32_t k = std::max(batch.interleave, 1u);
    push.interleave = k;
    push.vpl_offset = uint32_t(batch.vpl_offset % (k * k));
    const gpu::Image* target = &m_accumulation;
    if (k > 1) {
        if (k > shared::kMaxInterleave || !batch.interleaved || batch.add_emission ||
            batch.interleaved->width() != width || batch.interleaved->height() != height) {
            throw gpu::GpuError(
                "shading pass: interleaving needs K ≤ 8, an image of the accumulation's size and "
                "no emission");
        }
        target = batch.interleaved;
    }
    std::vector<gpu::Resource> resources{&g_buffer, target, &m_vpls, shadows};
    if (m_features.has_directional() || m_features.specular_chains) resources.push_back(ortho);
    if (m_features.specular_chains) {
        if (!batch.chains) throw gpu::GpuError("shading pass: a chain program without records");
        resources.push_back(batch.chains);
    }
    // Interleaved: one workgroup layer per pixel class, each invocation a pixel K apart.
    const uint32_t span = kShadingGroupSize * k;
    cmd.dispatch(*m_pipeline, resources, gpu::push_bytes(push), (width + span - 1) / span,
                 (height + span - 1) / span, k * k);
}

}  // namespace mvpl::render
