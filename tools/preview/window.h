#pragma once
// The preview's GLFW window and what the user did in it since the last poll. Vulkan-free to
// include (the surface comes back as the opaque handle of engine/gpu/swapchain.h).
#include <cstdint>
#include <string>
#include <vector>

#include "engine/gpu/swapchain.h"

struct GLFWwindow;

namespace mvpl::preview {

// Input gathered between two polls. Drags in pixels; keys by name (r, plus, minus, m, c, p,
// tab, escape), in the order pressed.
struct Input {
    float orbit_x = 0.0f, orbit_y = 0.0f;  // left drag
    float pan_x = 0.0f, pan_y = 0.0f;      // middle or shift+left drag
    float look_x = 0.0f, look_y = 0.0f;    // right drag
    float wheel = 0.0f;                    // scroll steps, positive away from the user
    std::vector<std::string> keys;
    std::vector<std::string> drops;  // files dropped on the window, in the order dropped
    // WASD held now: forward (W − S), right (D − A), up (E − Q).
    int fly_forward = 0, fly_right = 0, fly_up = 0;
};

class Window {
public:
    // Initialises GLFW (throws UsageError when there is no window system to talk to).
    Window(const std::string& title, int width, int height);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    // For gpu::ContextOptions: GLFW's instance extensions and its presentation test.
    static std::vector<std::string> required_instance_extensions();
    static bool can_present(VkInstance instance, VkPhysicalDevice device, uint32_t queue_family);
    VkSurfaceKHR create_surface(VkInstance instance) const;
    // For Dear ImGui's GLFW backend (settings_panel.cpp).
    GLFWwindow* handle() const { return m_window; }

    void poll();
    Input take_input();
    bool close_requested() const;
    void framebuffer_size(uint32_t& width, uint32_t& height) const;
    void set_size(int width, int height);
    void set_title(const std::string& title);
    // Sleeps until an event or the timeout (idle frames: minimised, converged).
    void wait(double seconds);

    // GLFW callbacks.
    void on_key(int key, int action, int mods);
    void on_cursor(double x, double y);
    void on_scroll(double dy);
    void on_drop(int count, const char** paths);

private:
    GLFWwindow* m_window = nullptr;
    Input m_input;
    double m_cursor_x = 0.0, m_cursor_y = 0.0;
    bool m_cursor_known = false;
};

}  // namespace mvpl::preview
