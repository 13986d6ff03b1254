#pragma once
// Pass 3 (docs/design.md, "GPU passes"): for every pixel of the G-buffer, the sum over a batch of
// VPLs of their contributions (engine/light/vpl.h), visibility from the shadow pass, added into an
// RGBA32F accumulation image by a compute shader. Vulkan-free to include.
#include <cstdint>
#include <memory>
#include <span>

#include "engine/core/math.h"
#include "engine/gpu/buffer.h"
#include "engine/gpu/image.h"
#include "engine/gpu/spirv_cache.h"
#include "engine/light/vpl.h"
#include "engine/render/shader_program.h"
#include "engine/scene/bounds.h"

namespace mvpl::gpu {
class CommandList;
class ComputePipeline;
class Context;
}  // namespace mvpl::gpu

namespace mvpl::render {

struct ShadingBatch {
    Vec3 camera_position{0.0f};
    float d_min = 0.0f;         // clamping distance of the geometric term (world units)
    float vsl_radius = 0.0f;    // of the virtual spherical lights (world units); 0: point VPLs
    bool add_emission = false;  // add the G-buffer's emitted radiance (once per image)
    // From ShadowPass: the cube array and the directional maps; nullptr: unshadowed.
    const gpu::Image* shadows = nullptr;
    const gpu::Image* ortho_shadows = nullptr;
    // ChainLayer::records(): required by a program with ShaderFeatures::specular_chains.
    const gpu::Buffer* chains = nullptr;
    // Interleaved sampling (shaders/shared/interleave.h): K > 1 shades each pixel with its
    // class's share of the batch, times K², and stores that into `interleaved` (an RGBA32F
    // image of the accumulation's size, InterleaveFilter::shaded()) instead of adding it to the
    // accumulation; vpl_offset is the index of the batch's first VPL since begin().
    uint32_t interleave = 1;
    uint64_t vpl_offset = 0;
    const gpu::Image* interleaved = nullptr;
};

class ShadingPass {
public:
    // source: the generated shading shader for `features` (shader_program.h); nullptr: generated
    // here for `features`. A batch with a VPL or closure type that the features leave out (a VPL
    // the scene cannot produce, e.g. hand-made in a test) makes upload() regenerate the program
    // with that type added, once.
    ShadingPass(gpu::Context& context, uint32_t width, uint32_t height, uint32_t max_batch,
                const ShaderFeatures& features = ShaderFeatures::all(),
                const StageSource* source = nullptr, const gpu::SpirvCacheOptions& cache = {});
    ~ShadingPass();
    ShadingPass(const ShadingPass&) = delete;
    ShadingPass& operator=(const ShadingPass&) = delete;

    // Writes the batch into the VPL buffer: outside a recording, and not while a submitted
    // batch is still running (submit_and_wait guarantees that).
    // bounds: the scene's (the extent of directional VPLs' maps).
    void upload(std::span<const light::Vpl> batch, const scene::Bounds& bounds);
    // Records the clear of the accumulation image.
    void record_clear(gpu::CommandList& cmd);
    // Records the shading of the uploaded batch against g_buffer (GBufferPass::image()).
    void record(gpu::CommandList& cmd, const gpu::Image& g_buffer, const ShadingBatch& batch);

    const gpu::Image& accumulation() const { return m_accumulation; }
    const ShaderFeatures& features() const { return m_features; }

private:
    gpu::Context* m_context;
    gpu::Image m_accumulation;
    gpu::Buffer m_vpls;  // host-visible: written by upload()
    // Bound when a batch has no shadow maps (never read then).
    gpu::Image m_no_shadows;
    gpu::Image m_no_ortho_shadows;
    ShaderFeatures m_features;
    gpu::SpirvCacheOptions m_cache;
    std::unique_ptr<gpu::ComputePipeline> m_pipeline;
    uint32_t m_max_batch;
    uint32_t m_count = 0;
};

}  // namespace mvpl::render
