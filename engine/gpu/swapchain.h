#pragma once
// A window's swapchain on the Context's one queue, for `mvpl preview`: one frame in flight
// (lavapipe renders on the CPU, so overlapping frames would gain nothing), recreated when the
// framebuffer size changes or the window system says it is out of date, and idle while the
// window is minimised (a 0×0 framebuffer). Vulkan-free to include.
#include <cstdint>
#include <vector>

#include "engine/gpu/vk_fwd.h"

// NOLINTBEGIN(modernize-use-using): the spelling must match vulkan_core.h (see vk_fwd.h).
typedef struct VkSurfaceKHR_T* VkSurfaceKHR;
typedef struct VkSwapchainKHR_T* VkSwapchainKHR;
typedef struct VkSemaphore_T* VkSemaphore;
// NOLINTEND(modernize-use-using)

namespace mvpl::gpu {

class Context;

// What begin_frame hands out: a command buffer in the recording state and the acquired image,
// which is in VK_IMAGE_LAYOUT_UNDEFINED on entry and must be left in
// VK_IMAGE_LAYOUT_PRESENT_SRC_KHR. Its usage is colour attachment and transfer destination.
struct SwapchainFrame {
    VkCommandBuffer cmd = nullptr;
    VkImage image = nullptr;
    uint32_t width = 0;
    uint32_t height = 0;
};

class Swapchain {
public:
    // Takes ownership of surface (made by the window system for context.instance()); the
    // context must be presentable (ContextOptions::can_present).
    Swapchain(Context& context, VkSurfaceKHR surface, uint32_t width, uint32_t height);
    ~Swapchain();
    Swapchain(const Swapchain&) = delete;
    Swapchain& operator=(const Swapchain&) = delete;

    // Starts a frame for a framebuffer of width × height pixels: recreates the swapchain when
    // that size differs or the last present found it out of date, acquires an image and begins
    // recording. false: nothing to draw this time (minimised, or the image had to be recreated).
    bool begin_frame(uint32_t width, uint32_t height, SwapchainFrame& frame);
    // Ends recording, submits it (waiting for the acquired image) and presents; returns when the
    // GPU has finished the frame.
    void end_frame();

    uint32_t width() const { return m_width; }
    uint32_t height() const { return m_height; }
    // VkFormat of the images; *_SRGB formats encode on write, the UNORM ones take bytes as is.
    int format() const { return m_format; }
    bool srgb() const { return m_srgb; }
    uint32_t image_count() const { return uint32_t(m_images.size()); }
    uint32_t recreations() const { return m_recreations; }

private:
    // false when the surface is 0×0 now.
    bool recreate(uint32_t width, uint32_t height);
    void destroy_swapchain() noexcept;
    void release() noexcept;

    Context* m_context;
    VkSurfaceKHR m_surface = nullptr;
    VkSwapchainKHR m_swapchain = nullptr;
    std::vector<VkImage> m_images;
    // One per image: a semaphore may be reused only after the present that waited on it, which
    // is certain once that image is acquired again.
    std::vector<VkSemaphore> m_render_done;
    VkSemaphore m_acquired = nullptr;
    VkCommandPool m_pool = nullptr;
    VkCommandBuffer m_cmd = nullptr;
    VkFence m_fence = nullptr;
    int m_format = 0;
    bool m_srgb = false;
    int m_present_mode = 0;
    uint32_t m_width = 0;
    uint32_t m_height = 0;
    uint32_t m_requested_width = 0;  // the framebuffer size of the last recreation
    uint32_t m_requested_height = 0;
    uint32_t m_image_index = 0;
    uint32_t m_recreations = 0;
    bool m_out_of_date = true;
    bool m_recording = false;
};

}  // namespace mvpl::gpu
