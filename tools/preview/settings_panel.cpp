#include "tools/preview/settings_panel.h"

#include <imgui.h>
#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>

#include <array>

#include "engine/gpu/command_list.h"
#include "engine/gpu/context.h"
#include "engine/gpu/vk_check.h"
#include "tools/preview/panel_widgets.h"
#include "tools/preview/window.h"

namespace mvpl::preview {
namespace {

void check(VkResult result) {
    gpu::vk_check(result, "Dear ImGui's Vulkan backend");
}

// Drawn over the presented picture: its pixels are loaded, not cleared.
VkRenderPass make_render_pass(VkDevice device, VkFormat format) {
    VkAttachmentDescription color{};
    color.format = format;
    color.samples = VK_SAMPLE_COUNT_1_BIT;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    color.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    color.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    color.initialLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.finalLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
    const VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = 1;
    subpass.pColorAttachments = &ref;
    VkRenderPassCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO;
    info.attachmentCount = 1;
    info.pAttachments = &color;
    info.subpassCount = 1;
    info.pSubpasses = &subpass;
    VkRenderPass pass = VK_NULL_HANDLE;
    gpu::vk_check(vkCreateRenderPass(device, &info, nullptr, &pass), "vkCreateRenderPass");
    return pass;
}

VkDescriptorPool make_pool(VkDevice device) {
    const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4};
    VkDescriptorPoolCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
    info.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
    info.maxSets = 4;
    info.poolSizeCount = 1;
    info.pPoolSizes = &size;
    VkDescriptorPool pool = VK_NULL_HANDLE;
    gpu::vk_check(vkCreateDescriptorPool(device, &info, nullptr, &pool), "vkCreateDescriptorPool");
    return pool;
}

}  // namespace

struct SettingsPanel::Impl {
    gpu::Context* context = nullptr;
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkRenderPass render_pass = VK_NULL_HANDLE;
    VkDescriptorPool pool = VK_NULL_HANDLE;
    // The last frame's target; that frame has finished when the next one records
    // (Swapchain::end_frame waits), so they are replaced then.
    VkImageView view = VK_NULL_HANDLE;
    VkFramebuffer framebuffer = VK_NULL_HANDLE;
    bool laid_out = false;
    std::string env_file;  // the environment file being typed

    void release_target() {
        const VkDevice device = context->device();
        if (framebuffer) vkDestroyFramebuffer(device, framebuffer, nullptr);
        if (view) vkDestroyImageView(device, view, nullptr);
        framebuffer = VK_NULL_HANDLE;
        view = VK_NULL_HANDLE;
    }
    void make_target(const gpu::SwapchainFrame& frame);
};

SettingsPanel::SettingsPanel(gpu::Context& context, Window& window, int swapchain_format,
                             bool visible)
    : m_impl(std::make_unique<Impl>()), m_visible(visible) {
    Impl& m = *m_impl;
    m.context = &context;
    m.format = VkFormat(swapchain_format);
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini in the working directory
    ImGui::StyleColorsDark();
    // After the window's own callbacks, which ImGui's call in turn.
    ImGui_ImplGlfw_InitForVulkan(window.handle(), true);
    m.render_pass = make_render_pass(context.device(), m.format);
    m.pool = make_pool(context.device());
    ImGui_ImplVulkan_InitInfo info{};
    info.Instance = context.instance();
    info.PhysicalDevice = context.physical_device();
    info.Device = context.device();
    info.QueueFamily = context.queue_family();
    info.Queue = context.queue();
    info.DescriptorPool = m.pool;
    info.MinImageCount = 2;
    info.ImageCount = 2;  // one frame in flight (gpu::Swapchain): vertex buffers to spare
    info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    info.CheckVkResultFn = check;
    ImGui_ImplVulkan_Init(&info, m.render_pass);
    context.submit_and_wait(
        [](gpu::CommandList& list) { ImGui_ImplVulkan_CreateFontsTexture(list.handle()); });
    ImGui_ImplVulkan_DestroyFontUploadObjects();
}

SettingsPanel::~SettingsPanel() {
    Impl& m = *m_impl;
    m.context->wait_idle();
    m.release_target();
    ImGui_ImplVulkan_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    vkDestroyDescriptorPool(m.context->device(), m.pool, nullptr);
    vkDestroyRenderPass(m.context->device(), m.render_pass, nullptr);
}

bool SettingsPanel::wants_mouse() const {
    return m_visible && ImGui::GetIO().WantCaptureMouse;
}

bool SettingsPanel::wants_keyboard() const {
    return m_visible && ImGui::GetIO().WantCaptureKeyboard;
}

std::vector<ScriptEvent> SettingsPanel::build(const PanelValues& values) {
    std::vector<ScriptEvent> events;
    if (!m_visible) return events;
    ImGui_ImplVulkan_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    // Top right: the HUD's text is at the top left.
    const ImVec2 size = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(size.x - 8.0f, 8.0f), ImGuiCond_FirstUseEver,
                            ImVec2(1.0f, 0.0f));
    ImGui::SetNextWindowBgAlpha(0.85f);
    ImGui::Begin("settings (Tab hides)", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
    panel_widgets(values, m_impl->env_file, events);
    ImGui::End();
    ImGui::Render();
    m_impl->laid_out = true;
    return events;
}

void SettingsPanel::Impl::make_target(const gpu::SwapchainFrame& frame) {
    release_target();
    const VkDevice device = context->device();
    VkImageViewCreateInfo vi{};
    vi.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
    vi.image = frame.image;
    vi.viewType = VK_IMAGE_VIEW_TYPE_2D;
    vi.format = format;
    vi.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    gpu::vk_check(vkCreateImageView(device, &vi, nullptr, &view), "vkCreateImageView");
    VkFramebufferCreateInfo fi{};
    fi.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO;
    fi.renderPass = render_pass;
    fi.attachmentCount = 1;
    fi.pAttachments = &view;
    fi.width = frame.width;
    fi.height = frame.height;
    fi.layers = 1;
    gpu::vk_check(vkCreateFramebuffer(device, &fi, nullptr, &framebuffer), "vkCreateFramebuffer");
}

void SettingsPanel::record(const gpu::SwapchainFrame& frame) {
    Impl& m = *m_impl;
    if (!m_visible || !m.laid_out) return;
    m.laid_out = false;
    m.make_target(frame);
    // The present pass's blit (and its layout change to PRESENT_SRC) → the panel's drawing.
    VkImageMemoryBarrier barrier{};
    barrier.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER;
    barrier.srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT;
    barrier.dstAccessMask =
        VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    barrier.oldLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
    barrier.newLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = frame.image;
    barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdPipelineBarrier(frame.cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
                         VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, 0, 0, nullptr, 0, nullptr,
                         1, &barrier);
    VkRenderPassBeginInfo begin{};
    begin.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO;
    begin.renderPass = m.render_pass;
    begin.framebuffer = m.framebuffer;
    begin.renderArea.extent = {frame.width, frame.height};
    vkCmdBeginRenderPass(frame.cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
    ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), frame.cmd);
    vkCmdEndRenderPass(frame.cmd);
}

}  // namespace mvpl::preview
