#pragma once
// The GPU VPL renderer: G-buffer once per view, then per batch of VPLs the shadow cubes and the
// shading, accumulated into one linear radiance image (DESIGN.md, "GPU passes"). Each VPL's
// `power` is already divided by the number of light paths (vpl.h), so the resolve is a plain
// read-back; tonemapping happens when a PNG is written. Vulkan-free to include (pimpl).
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "engine/core/image.h"
#include "engine/light/vpl.h"
#include "engine/scene/scene.h"

namespace mvpl::gpu {
class Context;
}

namespace mvpl::render {

struct RenderOptions {
    uint32_t width = 256;
    uint32_t height = 256;
    uint32_t shadow_resolution = 256;  // side of a shadow cube face in texels
    uint32_t batch = 32;               // VPLs per shadow/shading batch
    // d_min = clamp · scene diagonal, the distance below which the geometric term stops growing.
    float clamp = 0.0f;
    bool shadows = true;  // false: every VPL unshadowed (tests, debugging)
    // Called after each batch with the number of VPLs it shaded (progress bars).
    std::function<void(size_t)> on_batch;
};

// GPU milliseconds per pass (GpuTimer), summed over batches.
struct RenderTimings {
    double g_buffer_ms = 0.0;
    double shadow_ms = 0.0;
    double shading_ms = 0.0;
    double total_ms = 0.0;  // the three above
    double wall_ms = 0.0;   // host time of render(), uploads and read-back included
    uint32_t batches = 0;
};

class VplRenderer {
public:
    // Uploads the scene's geometry once. The context must outlive the renderer.
    VplRenderer(gpu::Context& context, const scene::Scene& scene);
    ~VplRenderer();
    VplRenderer(const VplRenderer&) = delete;
    VplRenderer& operator=(const VplRenderer&) = delete;

    // Linear radiance seen by the scene camera, row 0 at the top. Emitted radiance of surfaces
    // seen directly is included once.
    Image render(const std::vector<light::Vpl>& vpls, const RenderOptions& options,
                 RenderTimings* timings = nullptr);

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

}  // namespace mvpl::render
