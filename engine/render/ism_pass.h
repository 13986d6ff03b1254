#pragma once
// Imperfect shadow maps (Ritschel et al. 2008; issue 14, "many small maps"): the shadow cubes of
// many low-power VPLs at once, from a fixed set of scene points (ism_points.h) instead of the
// triangles. A compute pass splats every point into every VPL's cube (one invocation per point
// and VPL, the nearest kept by atomicMin on a uint buffer: on lavapipe, a CPU rasteriser, that
// costs points × VPLs whatever the triangle count), and a second pass fills the holes the
// points leave by pull-push and stores the faces into the rasterised pass's cube array, in the
// first `resolution` rows and columns of each layer, where the shading pass reads them as it
// reads a small rasterised face (GpuVpl's face size). Vulkan-free to include.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "engine/gpu/buffer.h"
#include "engine/light/vpl.h"
#include "engine/render/ism_points.h"

namespace mvpl::gpu {
class CommandList;
class ComputePipeline;
class Context;
class Image;
}  // namespace mvpl::gpu

namespace mvpl::render {

class IsmPass {
public:
    // Points per scene: chosen on the Cornell box and the dragon (docs/results.md, "Imperfect
    // shadow maps").
    static constexpr uint32_t kDefaultPoints = 32768;
    static constexpr uint32_t kDefaultResolution = 32;
    // Pull-push fills holes up to 2^kFillLevels texels across.
    static constexpr uint32_t kFillLevels = 2;

    // points: the scene's (sample_ism_points); resolution: the face side (≤ kMaxIsmResolution);
    // max_batch: the cubes of the array record() writes into.
    IsmPass(gpu::Context& context, std::vector<IsmPoint> points, uint32_t resolution,
            uint32_t max_batch);
    ~IsmPass();
    IsmPass(const IsmPass&) = delete;
    IsmPass& operator=(const IsmPass&) = delete;

    uint32_t resolution() const { return m_resolution; }
    size_t point_count() const { return m_point_count; }

    // Writes the cube of batch[i] into layers 6·slots[i] … +5 of cubes for every i; near: the
    // distance below which points do not shadow (ShadowPass::near_distance).
    void record(gpu::CommandList& cmd, std::span<const light::Vpl> vpls,
                std::span<const uint32_t> slots, float near, const gpu::Image& cubes);

private:
    uint32_t m_resolution;
    uint32_t m_max_batch;
    size_t m_point_count;
    gpu::Buffer m_points;
    gpu::Buffer m_depths;  // max_batch · 6 · resolution² float bits, kShadowNoOccluder between
                           // batches (the resolve clears what it reads)
    gpu::Buffer m_vpls;    // IsmVpl × max_batch, written by the host before each submission
    std::unique_ptr<gpu::ComputePipeline> m_splat;
    std::unique_ptr<gpu::ComputePipeline> m_resolve;
};

}  // namespace mvpl::render
