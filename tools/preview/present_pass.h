#pragma once
// The preview's present pass: scale · accumulation + the mean emission + the CPU estimators'
// image, exposed and sRGB-encoded
// like the PNG writer (shaders/preview/present.comp), the HUD blended on top, blitted into the
// swapchain image. A capture reads the display image back before the HUD is drawn, so that a
// screenshot is the rendered picture only. Vulkan-free to include.
#include <cstdint>
#include <memory>
#include <vector>

#include "engine/core/image.h"
#include "engine/gpu/swapchain.h"

namespace mvpl::gpu {
class Context;
class Image;
}  // namespace mvpl::gpu

namespace mvpl::preview {

struct HudBitmap;

struct PresentParams {
    double scale = 1.0;  // the VPL stream's scale()
    float exposure = 0.0f;
    bool hud = true;
    // Show the CPU image alone (a view such as albedo) instead of adding it to the radiance.
    bool cpu_image_only = false;
};

class PresentPass {
public:
    // linear_target: the swapchain format is *_SRGB (it encodes on write).
    PresentPass(gpu::Context& context, bool linear_target);
    ~PresentPass();
    PresentPass(const PresentPass&) = delete;
    PresentPass& operator=(const PresentPass&) = delete;

    // Uploads the HUD text image (outside a frame's recording).
    void set_hud(const HudBitmap& hud);
    // Uploads the CPU estimators' image that is added to the VPLs' (outside a frame's
    // recording); it must have the accumulation's size. An empty image: none.
    void set_cpu_image(const Image& image);
    // Records into frame.cmd. The display image has the frame's size and shows the accumulation
    // scaled to it (nearest neighbour; 1:1 when the sizes agree). emission: VplRenderer::emission()
    // (Σ over the G-buffers drawn, their count in alpha). capture: read the encoded picture back
    // (captured() after Swapchain::end_frame).
    void record(const gpu::SwapchainFrame& frame, const gpu::Image& accumulation,
                const gpu::Image& emission, const PresentParams& params, bool capture);
    // RGBA8, rows top first, of the last capture; width × height of that frame.
    std::vector<uint8_t> captured(uint32_t& width, uint32_t& height) const;

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

}  // namespace mvpl::preview
