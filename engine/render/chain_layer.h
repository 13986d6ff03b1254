#pragma once
// The second receiver layer of the shading pass (issue 15, specular chains): for each sub-pixel
// position, the CPU follows every pixel's camera path through glossy vertices
// (light/specular_chain.h, with the oracle's random numbers) and writes the receiver it ends on
// into a storage buffer that the shading pass reads beside the G-buffer; the emitted radiance the
// chains meet is in the same records, which the emission pass adds as it adds the G-buffer's
// (render/emission_sum.h).
// Built only for scenes with a material that may be continued. Vulkan-free to include.
#include <cstdint>
#include <memory>
#include <vector>

#include "engine/core/math.h"
#include "engine/gpu/buffer.h"
#include "engine/light/chain_options.h"
#include "engine/light/vpl_contribution.h"
#include "engine/scene/scene.h"
#include "shaders/shared/chain_record.h"

namespace mvpl::gpu {
class Context;
}
namespace mvpl::trace {
class Accel;
}
namespace mvpl::light {
class LightSampler;
}

namespace mvpl::render {

// A receiver as the GPU reads it (state kChainReceiver): a chain's rough end, or a row of the
// reduced matrix (matrix_pass.h).
shared::ChainRecord receiver_record(const light::Receiver& receiver, const Rgb& throughput,
                                    uint32_t max_vpl_length);

class ChainLayer {
public:
    ChainLayer(gpu::Context& context, const scene::Scene& scene, const trace::Accel& accel,
               uint32_t width, uint32_t height);
    ~ChainLayer();
    ChainLayer(const ChainLayer&) = delete;
    ChainLayer& operator=(const ChainLayer&) = delete;

    // Writes the records of sub-pixel `position` (at `offset` in the pixel) seen by `camera`:
    // outside a running batch, and one position per submission (the buffer holds one).
    void trace(const scene::Camera& camera, Vec2 offset, uint64_t position,
               const light::ChainOptions& options, uint64_t seed);

    const gpu::Buffer& records() const { return m_records; }
    uint64_t rays() const { return m_rays; }
    uint32_t width() const { return m_width; }
    uint32_t height() const { return m_height; }

private:
    const scene::Scene& m_scene;
    const trace::Accel& m_accel;
    // For the chains' light samples at glossy vertices, as the oracle's (specular_chain.h).
    std::unique_ptr<const light::LightSampler> m_lights;
    uint32_t m_width;
    uint32_t m_height;
    gpu::Buffer m_records;  // host-visible ChainRecord per pixel
    uint64_t m_rays = 0;
    // Per pixel, whether the ray through its centre is continued (light::pixel_centre_continues)
    // for the view and chain roughness below: computed once per view, not per position; empty
    // without extra samples (ChainOptions::emission_samples ≤ 1).
    void update_centres(const scene::Camera& camera, const light::ChainOptions& options);
    std::vector<uint8_t> m_centres;
    scene::Camera m_centres_camera;
    float m_centres_roughness = -1.0f;
};

}  // namespace mvpl::render
