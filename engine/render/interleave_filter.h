#pragma once
// The geometry-aware filter of interleaved sampling (Keller & Heidrich 2001;
// shaders/shared/interleave.h): the shading pass adds each pixel's share of a batch, K² times,
// into shaded(), and record() adds to the accumulation the mean of those over each pixel's K×K
// neighbours on the same surface of the batches' G-buffer, then clears shaded(). The filter is
// linear in shaded(), so one pass filters the batches of a sub-pixel position (or those of one
// accumulate() call) as a pass per batch would; on lavapipe a pass cost about 11 ms at 256², a
// third of a 32-VPL batch on the Cornell box. Vulkan-free to include.
#include <cstdint>
#include <memory>

#include "engine/gpu/buffer.h"
#include "engine/gpu/image.h"

namespace mvpl::gpu {
class CommandList;
class ComputePipeline;
class Context;
}  // namespace mvpl::gpu

namespace mvpl::render {

class InterleaveFilter {
public:
    // k in 2 … shared::kMaxInterleave.
    InterleaveFilter(gpu::Context& context, uint32_t width, uint32_t height, uint32_t k);
    ~InterleaveFilter();
    InterleaveFilter(const InterleaveFilter&) = delete;
    InterleaveFilter& operator=(const InterleaveFilter&) = delete;

    // The interleaved batch image the shading pass writes (ShadingBatch::interleaved).
    const gpu::Image& shaded() const { return m_shaded; }
    uint32_t k() const { return m_k; }
    // Adds the filtered shaded() into accumulation, with the neighbourhoods of g_buffer
    // (GBufferPass::image()) and, where specular chains are traced, of their records
    // (ChainLayer::records(); nullptr: none), then clears shaded(); after a barrier that follows
    // the shading, and followed by one.
    void record(gpu::CommandList& cmd, const gpu::Image& g_buffer, const gpu::Image& accumulation,
                const gpu::Buffer* chains = nullptr);
    // Clears shaded() (before the first batch of a render).
    void record_clear(gpu::CommandList& cmd);

private:
    gpu::Image m_shaded;
    gpu::Buffer m_no_chains;  // bound where there are no chain records (never read then)
    std::unique_ptr<gpu::ComputePipeline> m_pipeline;
    uint32_t m_k;
};

}  // namespace mvpl::render
