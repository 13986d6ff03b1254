#include "engine/gpu/swapchain.h"

#include <vulkan/vulkan.h>

#include <algorithm>
#include <string>

#include "engine/gpu/context.h"
#include "engine/gpu/gpu_error.h"
#include "engine/gpu/vk_check.h"

namespace mvpl::gpu {
namespace {

bool is_srgb(VkFormat format) {
    return format == VK_FORMAT_B8G8R8A8_SRGB || format == VK_FORMAT_R8G8B8A8_SRGB ||
           format == VK_FORMAT_A8B8G8R8_SRGB_PACK32;
}

// UNORM first: the present pass encodes sRGB itself, exactly as the PNG writer does, so that
// a screenshot and the window agree byte for byte.
VkSurfaceFormatKHR pick_format(VkPhysicalDevice physical, VkSurfaceKHR surface) {
    uint32_t count = 0;
    vk_check(vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &count, nullptr),
             "vkGetPhysicalDeviceSurfaceFormatsKHR");
    std::vector<VkSurfaceFormatKHR> formats(count);
    vk_check(vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &count, formats.data()),
             "vkGetPhysicalDeviceSurfaceFormatsKHR");
    if (formats.empty()) throw GpuError("the window surface offers no format");
    for (VkFormat wanted : {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM}) {
        for (const VkSurfaceFormatKHR& f : formats) {
            if (f.format == wanted && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) return f;
        }
    }
    return formats[0];
}

// Mailbox (no tearing, never blocks) or immediate: a progressive renderer should not wait for a
// vertical blank between batches. FIFO is the one mode every driver has.
VkPresentModeKHR pick_present_mode(VkPhysicalDevice physical, VkSurfaceKHR surface) {
    uint32_t count = 0;
    vk_check(vkGetPhysicalDeviceSurfacePresentModesKHR(physical, surface, &count, nullptr),
             "vkGetPhysicalDeviceSurfacePresentModesKHR");
    std::vector<VkPresentModeKHR> modes(count);
    vk_check(vkGetPhysicalDeviceSurfacePresentModesKHR(physical, surface, &count, modes.data()),
             "vkGetPhysicalDeviceSurfacePresentModesKHR");
    for (VkPresentModeKHR wanted : {VK_PRESENT_MODE_MAILBOX_KHR, VK_PRESENT_MODE_IMMEDIATE_KHR}) {
        if (std::find(modes.begin(), modes.end(), wanted) != modes.end()) return wanted;
    }
    return VK_PRESENT_MODE_FIFO_KHR;
}

VkSemaphore make_semaphore(VkDevice device) {
    VkSemaphoreCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO;
    VkSemaphore semaphore = VK_NULL_HANDLE;
    vk_check(vkCreateSemaphore(device, &info, nullptr, &semaphore), "vkCreateSemaphore");
    return semaphore;
}

}  // namespace

Swapchain::Swapchain(Context& context, VkSurfaceKHR surface, uint32_t width, uint32_t height)
    : m_context(&context), m_surface(surface), m_width(width), m_height(height) {
    const VkDevice device = context.device();
    try {
        if (!context.presentable())
            throw GpuError("Swapchain on a headless Context (set ContextOptions::can_present)");
        VkBool32 supported = VK_FALSE;
        vk_check(vkGetPhysicalDeviceSurfaceSupportKHR(context.physical_device(),
                                                      context.queue_family(), surface, &supported),
                 "vkGetPhysicalDeviceSurfaceSupportKHR");
        if (!supported) throw GpuError("the device's queue cannot present to this window");
        const VkSurfaceFormatKHR format = pick_format(context.physical_device(), surface);
        m_format = int(format.format);
        m_srgb = is_srgb(format.format);
        m_present_mode = int(pick_present_mode(context.physical_device(), surface));

        VkCommandPoolCreateInfo pool_info{};
        pool_info.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
        pool_info.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
        pool_info.queueFamilyIndex = context.queue_family();
        vk_check(vkCreateCommandPool(device, &pool_info, nullptr, &m_pool), "vkCreateCommandPool");
        VkCommandBufferAllocateInfo cmd_info{};
        cmd_info.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
        cmd_info.commandPool = m_pool;
        cmd_info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        cmd_info.commandBufferCount = 1;
        vk_check(vkAllocateCommandBuffers(device, &cmd_info, &m_cmd), "vkAllocateCommandBuffers");
        VkFenceCreateInfo fence_info{};
        fence_info.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
        vk_check(vkCreateFence(device, &fence_info, nullptr, &m_fence), "vkCreateFence");
        m_acquired = make_semaphore(device);
        context.set_debug_name(VK_OBJECT_TYPE_COMMAND_BUFFER, uint64_t(m_cmd), "present");
    } catch (...) {
        release();
        throw;
    }
}

Swapchain::~Swapchain() {
    release();
}

void Swapchain::release() noexcept {
    if (!m_context) return;
    const VkDevice device = m_context->device();
    vkDeviceWaitIdle(device);
    destroy_swapchain();
    if (m_acquired) vkDestroySemaphore(device, m_acquired, nullptr);
    if (m_fence) vkDestroyFence(device, m_fence, nullptr);
    if (m_pool) vkDestroyCommandPool(device, m_pool, nullptr);
    if (m_surface) vkDestroySurfaceKHR(m_context->instance(), m_surface, nullptr);
    m_acquired = nullptr;
    m_fence = nullptr;
    m_pool = nullptr;
    m_surface = nullptr;
    m_context = nullptr;
}

void Swapchain::destroy_swapchain() noexcept {
    const VkDevice device = m_context->device();
    for (VkSemaphore s : m_render_done)
        vkDestroySemaphore(device, s, nullptr);
    m_render_done.clear();
    m_images.clear();
    if (m_swapchain) vkDestroySwapchainKHR(device, m_swapchain, nullptr);
    m_swapchain = nullptr;
}

bool Swapchain::recreate(uint32_t width, uint32_t height) {
    const VkDevice device = m_context->device();
    VkSurfaceCapabilitiesKHR caps{};
    vk_check(
        vkGetPhysicalDeviceSurfaceCapabilitiesKHR(m_context->physical_device(), m_surface, &caps),
        "vkGetPhysicalDeviceSurfaceCapabilitiesKHR");
    VkExtent2D extent = caps.currentExtent;
    if (extent.width == UINT32_MAX) {  // the surface takes the swapchain's size
        extent.width = std::clamp(width, caps.minImageExtent.width, caps.maxImageExtent.width);
        extent.height = std::clamp(height, caps.minImageExtent.height, caps.maxImageExtent.height);
    }
    if (extent.width == 0 || extent.height == 0) return false;
    m_requested_width = width;
    m_requested_height = height;

    vk_check(vkDeviceWaitIdle(device), "vkDeviceWaitIdle");
    uint32_t count = std::max(caps.minImageCount + 1, 2u);
    if (caps.maxImageCount > 0) count = std::min(count, caps.maxImageCount);
    VkSwapchainCreateInfoKHR info{};
    info.sType = VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR;
    info.surface = m_surface;
    info.minImageCount = count;
    info.imageFormat = VkFormat(m_format);
    info.imageColorSpace = VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
    info.imageExtent = extent;
    info.imageArrayLayers = 1;
    info.imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.preTransform = (caps.supportedTransforms & VK_SURFACE_TRANSFORM_IDENTITY_BIT_KHR)
                            ? VK_SURFACE_TRANSFORM_IDENTITY_BIT_KHR
                            : caps.currentTransform;
    info.compositeAlpha = (caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR)
                              ? VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR
                              : VkCompositeAlphaFlagBitsKHR(caps.supportedCompositeAlpha &
                                                            -caps.supportedCompositeAlpha);
    info.presentMode = VkPresentModeKHR(m_present_mode);
    info.clipped = VK_TRUE;
    info.oldSwapchain = m_swapchain;
    VkSwapchainKHR created = VK_NULL_HANDLE;
    vk_check(vkCreateSwapchainKHR(device, &info, nullptr, &created), "vkCreateSwapchainKHR");
    destroy_swapchain();
    m_swapchain = created;

    vk_check(vkGetSwapchainImagesKHR(device, m_swapchain, &count, nullptr),
             "vkGetSwapchainImagesKHR");
    m_images.resize(count);
    vk_check(vkGetSwapchainImagesKHR(device, m_swapchain, &count, m_images.data()),
             "vkGetSwapchainImagesKHR");
    for (uint32_t i = 0; i < count; ++i)
        m_render_done.push_back(make_semaphore(device));
    m_width = extent.width;
    m_height = extent.height;
    m_out_of_date = false;
    ++m_recreations;
    return true;
}

bool Swapchain::begin_frame(uint32_t width, uint32_t height, SwapchainFrame& frame) {
    if (m_recording) throw GpuError("Swapchain::begin_frame twice without end_frame");
    if (width == 0 || height == 0) return false;  // minimised: nothing to present to
    // Compared with the size asked for, not the extent granted: a surface that grants another
    // (HiDPI scaling, a clamp) must not be recreated every frame.
    if (m_out_of_date || !m_swapchain || width != m_requested_width ||
        height != m_requested_height) {
        if (!recreate(width, height)) return false;
    }
    const VkDevice device = m_context->device();
    const VkResult acquired = vkAcquireNextImageKHR(device, m_swapchain, UINT64_MAX, m_acquired,
                                                    VK_NULL_HANDLE, &m_image_index);
    if (acquired == VK_ERROR_OUT_OF_DATE_KHR) {
        m_out_of_date = true;  // the semaphore was not signalled: it stays reusable
        return false;
    }
    if (acquired != VK_SUBOPTIMAL_KHR) vk_check(acquired, "vkAcquireNextImageKHR");
    if (acquired == VK_SUBOPTIMAL_KHR) m_out_of_date = true;  // draw this one, recreate next time

    vk_check(vkResetCommandBuffer(m_cmd, 0), "vkResetCommandBuffer");
    VkCommandBufferBeginInfo begin{};
    begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    vk_check(vkBeginCommandBuffer(m_cmd, &begin), "vkBeginCommandBuffer");
    m_recording = true;
    frame.cmd = m_cmd;
    frame.image = m_images[m_image_index];
    frame.width = m_width;
    frame.height = m_height;
    return true;
}

void Swapchain::end_frame() {
    if (!m_recording) throw GpuError("Swapchain::end_frame without begin_frame");
    m_recording = false;
    vk_check(vkEndCommandBuffer(m_cmd), "vkEndCommandBuffer");

    // The recorded commands first touch the image in a transfer (a blit or a clear); that stage
    // waits for the acquire.
    VkSemaphoreSubmitInfo wait{};
    wait.sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO;
    wait.semaphore = m_acquired;
    wait.stageMask = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
    VkSemaphoreSubmitInfo signal{};
    signal.sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO;
    signal.semaphore = m_render_done[m_image_index];
    signal.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    VkCommandBufferSubmitInfo cmd_info{};
    cmd_info.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO;
    cmd_info.commandBuffer = m_cmd;
    VkSubmitInfo2 submit{};
    submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO_2;
    submit.waitSemaphoreInfoCount = 1;
    submit.pWaitSemaphoreInfos = &wait;
    submit.commandBufferInfoCount = 1;
    submit.pCommandBufferInfos = &cmd_info;
    submit.signalSemaphoreInfoCount = 1;
    submit.pSignalSemaphoreInfos = &signal;
    const VkQueue queue = m_context->queue();
    vk_check(vkQueueSubmit2(queue, 1, &submit, m_fence), "vkQueueSubmit2");

    VkPresentInfoKHR present{};
    present.sType = VK_STRUCTURE_TYPE_PRESENT_INFO_KHR;
    present.waitSemaphoreCount = 1;
    present.pWaitSemaphores = &m_render_done[m_image_index];
    present.swapchainCount = 1;
    present.pSwapchains = &m_swapchain;
    present.pImageIndices = &m_image_index;
    const VkResult presented = vkQueuePresentKHR(queue, &present);
    if (presented == VK_ERROR_OUT_OF_DATE_KHR || presented == VK_SUBOPTIMAL_KHR) {
        m_out_of_date = true;
    } else {
        vk_check(presented, "vkQueuePresentKHR");
    }
    const VkDevice device = m_context->device();
    vk_check(vkWaitForFences(device, 1, &m_fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
    vk_check(vkResetFences(device, 1, &m_fence), "vkResetFences");
}

}  // namespace mvpl::gpu
