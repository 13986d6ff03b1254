#pragma once
// The preview's settings panel (Tab shows and hides it): Dear ImGui with the GLFW and Vulkan
// backends of Debian's libimgui-dev, drawn onto the swapchain image after the present pass, so
// that screenshots (read back before) never hold it. Each edit comes back as an event of the
// script's format (script.h), which the window applies as it applies the script's: one path
// for both. Vulkan-free to include.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "engine/core/color.h"
#include "engine/gpu/swapchain.h"
#include "tools/preview/script.h"

namespace mvpl::gpu {
class Context;
}

namespace mvpl::preview {

class Window;

// What the panel shows: the settings as they are now.
struct PanelValues {
    std::string sampler;
    uint64_t paths_per_frame = 0;
    float budget_ms = 0.0f;
    bool clamping = false;
    float clamp = 0.0f;  // the distance, × the scene diagonal, whether clamping or not
    bool compensate = false, caustics = false, chains = false;
    float vsl = 0.0f;
    int max_depth = 0;
    uint32_t shadow_resolution = 0;
    float exposure = 0.0f;
    Rgb env_color{1.0f};
    float env_scale = 1.0f, env_rotation = 0.0f;
    std::string env_map;
    int cameras = 0;  // the file's
    float fov_degrees = 0.0f;
    std::string view;  // image, albedo, normal, depth, vpls
};

class SettingsPanel {
public:
    // swapchain_format: the VkFormat of the images it draws onto.
    SettingsPanel(gpu::Context& context, Window& window, int swapchain_format, bool visible);
    ~SettingsPanel();
    SettingsPanel(const SettingsPanel&) = delete;
    SettingsPanel& operator=(const SettingsPanel&) = delete;

    bool visible() const { return m_visible; }
    void toggle() { m_visible = !m_visible; }
    // The mouse or keyboard is the panel's (over it, or typing in it): not the camera's.
    bool wants_mouse() const;
    bool wants_keyboard() const;
    // Lays the panel out for this frame; the edits made, as events. Nothing while hidden.
    std::vector<ScriptEvent> build(const PanelValues& values);
    // Draws what build() laid out onto frame.image (after the present pass has blitted to it,
    // in VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, where it leaves it).
    void record(const gpu::SwapchainFrame& frame);

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
    bool m_visible;
};

}  // namespace mvpl::preview
