#pragma once
// The emitted radiance seen directly, averaged over the sub-pixel positions of a progressive
// render (engine/core/subpixel.h): VPL light is summed batch by batch at each batch's position,
// and emission, which needs no VPL, is summed once per G-buffer drawn, with the count of
// G-buffers in alpha so that the resolve and the preview divide per pixel. Vulkan-free to include.
#include <cstdint>
#include <memory>
#include <vector>

#include "engine/gpu/buffer.h"
#include "engine/gpu/image.h"

namespace mvpl::gpu {
class CommandList;
class ComputePipeline;
class Context;
}  // namespace mvpl::gpu

namespace mvpl::render {

class EmissionSum {
public:
    EmissionSum(gpu::Context& context, uint32_t width, uint32_t height);
    ~EmissionSum();
    EmissionSum(const EmissionSum&) = delete;
    EmissionSum& operator=(const EmissionSum&) = delete;

    // The radiance that pixels no surface covers receive (the environment through each pixel's
    // centre), RGBA32F row by row; without one they receive nothing.
    void set_background(const std::vector<float>& rgba);

    void record_clear(gpu::CommandList& cmd);
    // Adds the emission layer of g_buffer (GBufferPass::image(), after a barrier), the emitted
    // radiance in `chain_records` (ChainLayer::records(), when the render traces specular
    // chains) and 1 to alpha.
    void record_add(gpu::CommandList& cmd, const gpu::Image& g_buffer,
                    const gpu::Buffer* chain_records = nullptr);

    // RGBA32F: rgb Σ emitted radiance, a the number of G-buffers summed.
    const gpu::Image& image() const { return m_sum; }

private:
    gpu::Context& m_context;
    gpu::Image m_sum;
    gpu::Image m_background;  // 1×1 and unread until set_background
    gpu::Buffer m_no_chains;  // bound, unread, where no chain records are given
    bool m_has_background = false;
    std::unique_ptr<gpu::ComputePipeline> m_pipeline;
};

}  // namespace mvpl::render
