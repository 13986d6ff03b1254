#include "tools/preview/present_pass.h"

#include <vulkan/vulkan.h>

#include <array>
#include <cmath>
#include <cstring>

#include "engine/gpu/buffer.h"
#include "engine/gpu/compute_pipeline.h"
#include "engine/gpu/context.h"
#include "engine/gpu/image.h"
#include "engine/gpu/shader_compiler.h"
#include "engine/gpu/vk_check.h"
#include "shaders/shared/present_push.h"
#include "tools/preview/hud.h"

namespace mvpl::preview {
namespace {

using Push = shared::PresentPush;

constexpr uint32_t kGroup = 8;  // present.comp's local size

void image_barrier(VkCommandBuffer cmd, VkImage image, VkPipelineStageFlags2 src_stage,
                   VkAccessFlags2 src_access, VkPipelineStageFlags2 dst_stage,
                   VkAccessFlags2 dst_access, VkImageLayout from, VkImageLayout to) {
    VkImageMemoryBarrier2 b{};
    b.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2;
    b.srcStageMask = src_stage;
    b.srcAccessMask = src_access;
    b.dstStageMask = dst_stage;
    b.dstAccessMask = dst_access;
    b.oldLayout = from;
    b.newLayout = to;
    b.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image;
    b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkDependencyInfo d{};
    d.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO;
    d.imageMemoryBarrierCount = 1;
    d.pImageMemoryBarriers = &b;
    vkCmdPipelineBarrier2(cmd, &d);
}

void memory_barrier(VkCommandBuffer cmd, VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access,
                    VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access) {
    VkMemoryBarrier2 b{};
    b.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER_2;
    b.srcStageMask = src_stage;
    b.srcAccessMask = src_access;
    b.dstStageMask = dst_stage;
    b.dstAccessMask = dst_access;
    VkDependencyInfo d{};
    d.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO;
    d.memoryBarrierCount = 1;
    d.pMemoryBarriers = &b;
    vkCmdPipelineBarrier2(cmd, &d);
}

// The display image lives in GENERAL (gpu::Image); copies and blits read it in
// TRANSFER_SRC_OPTIMAL, which the validation layer asks for and real GPUs may prefer.
void to_transfer_source(VkCommandBuffer cmd, VkImage image) {
    image_barrier(cmd, image, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                  VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                  VK_ACCESS_2_TRANSFER_READ_BIT, VK_IMAGE_LAYOUT_GENERAL,
                  VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
}

void to_general(VkCommandBuffer cmd, VkImage image, VkPipelineStageFlags2 dst_stage,
                VkAccessFlags2 dst_access) {
    image_barrier(cmd, image, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_NONE, dst_stage,
                  dst_access, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL);
}

gpu::ComputeLayout present_layout() {
    gpu::ComputeLayout layout;
    layout.bindings = {gpu::BindingType::storage_image, gpu::BindingType::storage_image,
                       gpu::BindingType::storage_image, gpu::BindingType::storage_image,
                       gpu::BindingType::storage_image};
    layout.push_constant_bytes = sizeof(Push);
    return layout;
}

}  // namespace

struct PresentPass::Impl {
    gpu::Context* context;
    bool linear_target;
    gpu::ComputePipeline pipeline;
    // Its own pool: the Context's transient pool is reset only by submit_and_wait, which idle
    // frames (a converged picture) never call.
    VkDescriptorPool pool = VK_NULL_HANDLE;
    VkDescriptorSet set = VK_NULL_HANDLE;
    gpu::Image display;
    gpu::Image hud;  // 1×1 transparent until the first set_hud
    gpu::Image cpu;  // 1×1 black while there is no CPU image
    bool cpu_active = false;
    uint32_t hud_width = 0;
    uint32_t hud_height = 0;
    int32_t hud_x = 0;
    int32_t hud_y = 0;
    gpu::Buffer readback;
    uint32_t captured_width = 0;
    uint32_t captured_height = 0;

    Impl(gpu::Context& c, bool linear)
        : context(&c),
          linear_target(linear),
          pipeline(c, gpu::compile_embedded_shader("preview/present.comp"), present_layout(),
                   "preview/present.comp") {}

    // The display image at the frame's size and, for a capture, a readback buffer that holds it.
    void fit(uint32_t width, uint32_t height, bool capture);
    // Points the set's five bindings at the images.
    void bind(const gpu::Image& accumulation, const gpu::Image& emission);
    // One pass of present.comp over the display image, with the HUD or without.
    void dispatch(VkCommandBuffer cmd, Push push, bool with_hud) const;
    // The picture without the HUD copied into the readback buffer, then the HUD drawn over it.
    void capture(VkCommandBuffer cmd, const Push& push, bool with_hud);
    // The display image blitted into the swapchain image, which is left ready to present.
    void blit(VkCommandBuffer cmd, const gpu::SwapchainFrame& frame) const;
};

void PresentPass::Impl::fit(uint32_t width, uint32_t height, bool capture) {
    if (!display.valid() || display.width() != width || display.height() != height) {
        gpu::ImageDesc desc;
        desc.width = width;
        desc.height = height;
        desc.format = gpu::Format::rgba8_unorm;
        desc.usage = gpu::ImageUsage::storage;
        display = gpu::Image(*context, desc, "preview display");
    }
    if (capture && (!readback.valid() || readback.size() < uint64_t(width) * height * 4)) {
        readback = gpu::Buffer(*context, uint64_t(width) * height * 4, gpu::BufferUsage::none,
                               gpu::MemoryLocation::readback, "preview screenshot");
    }
}

void PresentPass::Impl::bind(const gpu::Image& accumulation, const gpu::Image& emission) {
    const std::array<const gpu::Image*, 5> images{&accumulation, &emission, &display, &hud, &cpu};
    std::array<VkDescriptorImageInfo, 5> infos{};
    std::array<VkWriteDescriptorSet, 5> writes{};
    for (size_t i = 0; i < images.size(); ++i) {
        infos[i].imageView = images[i]->view();
        infos[i].imageLayout = VK_IMAGE_LAYOUT_GENERAL;
        writes[i].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
        writes[i].dstSet = set;
        writes[i].dstBinding = uint32_t(i);
        writes[i].descriptorCount = 1;
        writes[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
        writes[i].pImageInfo = &infos[i];
    }
    vkUpdateDescriptorSets(context->device(), uint32_t(writes.size()), writes.data(), 0, nullptr);
}

void PresentPass::Impl::dispatch(VkCommandBuffer cmd, Push push, bool with_hud) const {
    push.hud_width = with_hud ? hud_width : 0;
    push.hud_height = with_hud ? hud_height : 0;
    push.hud_x = hud_x;
    push.hud_y = hud_y;
    vkCmdPushConstants(cmd, pipeline.pipeline_layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push,
                       &push);
    vkCmdDispatch(cmd, (push.width + kGroup - 1) / kGroup, (push.height + kGroup - 1) / kGroup, 1);
}

void PresentPass::Impl::capture(VkCommandBuffer cmd, const Push& push, bool with_hud) {
    dispatch(cmd, push, false);
    to_transfer_source(cmd, display.handle());
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {push.width, push.height, 1};
    vkCmdCopyImageToBuffer(cmd, display.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           readback.handle(), 1, &region);
    memory_barrier(cmd, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                   VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
    captured_width = push.width;
    captured_height = push.height;
    if (with_hud) {
        // The copy read what the HUD pass overwrites.
        to_general(cmd, display.handle(), VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                   VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
        dispatch(cmd, push, true);
        to_transfer_source(cmd, display.handle());
    }
}

void PresentPass::Impl::blit(VkCommandBuffer cmd, const gpu::SwapchainFrame& frame) const {
    // The acquire semaphore is waited for at the transfer stage (Swapchain::end_frame).
    image_barrier(cmd, frame.image, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_NONE,
                  VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                  VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
    VkImageBlit region{};
    region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.srcOffsets[1] = {int32_t(display.width()), int32_t(display.height()), 1};
    region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.dstOffsets[1] = {int32_t(frame.width), int32_t(frame.height), 1};
    vkCmdBlitImage(cmd, display.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, frame.image,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region, VK_FILTER_NEAREST);
    image_barrier(cmd, frame.image, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                  VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE,
                  VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR);
    // Back to GENERAL, the layout gpu::Image keeps (the next frame's barrier orders the rest).
    to_general(cmd, display.handle(), VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
               VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT);
}

PresentPass::PresentPass(gpu::Context& context, bool linear_target)
    : m_impl(std::make_unique<Impl>(context, linear_target)) {
    Impl& m = *m_impl;
    const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 5};
    VkDescriptorPoolCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
    info.maxSets = 1;
    info.poolSizeCount = 1;
    info.pPoolSizes = &size;
    gpu::vk_check(vkCreateDescriptorPool(context.device(), &info, nullptr, &m.pool),
                  "vkCreateDescriptorPool");
    const VkDescriptorSetLayout layout = m.pipeline.set_layout();
    VkDescriptorSetAllocateInfo alloc{};
    alloc.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
    alloc.descriptorPool = m.pool;
    alloc.descriptorSetCount = 1;
    alloc.pSetLayouts = &layout;
    gpu::vk_check(vkAllocateDescriptorSets(context.device(), &alloc, &m.set),
                  "vkAllocateDescriptorSets");
    gpu::ImageDesc desc;
    desc.format = gpu::Format::rgba8_unorm;
    desc.usage = gpu::ImageUsage::storage;
    m.hud = gpu::Image(context, desc, "preview hud");
    m.hud.upload(std::vector<uint8_t>(4, 0));
    desc.format = gpu::Format::rgba32_float;
    m.cpu = gpu::Image(context, desc, "preview cpu image");
    m.cpu.upload(std::vector<float>(4, 0.0f));
}

void PresentPass::set_cpu_image(const Image& image) {
    Impl& m = *m_impl;
    m.cpu_active = image.width() > 0 && image.height() > 0;
    if (!m.cpu_active) return;
    const auto w = uint32_t(image.width()), h = uint32_t(image.height());
    if (m.cpu.width() != w || m.cpu.height() != h) {
        gpu::ImageDesc desc;
        desc.width = w;
        desc.height = h;
        desc.format = gpu::Format::rgba32_float;
        desc.usage = gpu::ImageUsage::storage;
        m.cpu = gpu::Image(*m.context, desc, "preview cpu image");
    }
    std::vector<float> rgba(size_t(w) * h * 4, 0.0f);
    for (size_t i = 0; i < size_t(w) * h; ++i)
        for (int c = 0; c < 3; ++c)
            rgba[4 * i + size_t(c)] = image.pixels()[i][c];
    m.cpu.upload(rgba);
}

PresentPass::~PresentPass() {
    Impl& m = *m_impl;
    m.context->wait_idle();
    vkDestroyDescriptorPool(m.context->device(), m.pool, nullptr);
}

void PresentPass::set_hud(const HudBitmap& hud) {
    Impl& m = *m_impl;
    if (hud.width == 0 || hud.height == 0) {
        m.hud_width = 0;
        return;
    }
    if (!m.hud.valid() || m.hud.width() != hud.width || m.hud.height() != hud.height) {
        gpu::ImageDesc desc;
        desc.width = hud.width;
        desc.height = hud.height;
        desc.format = gpu::Format::rgba8_unorm;
        desc.usage = gpu::ImageUsage::storage;
        m.hud = gpu::Image(*m.context, desc, "preview hud");
    }
    m.hud.upload(hud.rgba);
    m.hud_width = hud.width;
    m.hud_height = hud.height;
    m.hud_x = hud.x;
    m.hud_y = hud.y;
}

void PresentPass::record(const gpu::SwapchainFrame& frame, const gpu::Image& accumulation,
                         const gpu::Image& emission, const PresentParams& params, bool capture) {
    Impl& m = *m_impl;
    // The display image has the window's size; the accumulation may be smaller (camera moving).
    const uint32_t width = frame.width;
    const uint32_t height = frame.height;
    m.fit(width, height, capture);
    // The frame before has finished (Swapchain::end_frame waits), so the set is free to update.
    const bool cpu = m.cpu_active && m.cpu.width() == accumulation.width() &&
                     m.cpu.height() == accumulation.height();
    m.bind(accumulation, emission);

    const VkCommandBuffer cmd = frame.cmd;
    // The renderer's submissions (and the last frame's blit, which read the display image)
    // → this frame's shader.
    memory_barrier(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_WRITE_BIT,
                   VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                   VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m.pipeline.handle());
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m.pipeline.pipeline_layout(), 0, 1,
                            &m.set, 0, nullptr);
    Push push{};
    push.scale = float(params.scale);
    push.exposure_scale = std::exp2(params.exposure);
    push.width = width;
    push.height = height;
    push.source_width = accumulation.width();
    push.source_height = accumulation.height();
    push.linear_target = m.linear_target ? 1u : 0u;
    push.cpu_image = cpu ? (params.cpu_image_only ? 2u : 1u) : 0u;
    const bool hud = params.hud && m.hud_width > 0;
    if (capture) {
        m.capture(cmd, push, hud);
    } else {
        m.dispatch(cmd, push, hud);
        to_transfer_source(cmd, m.display.handle());
    }
    m.blit(cmd, frame);
}

std::vector<uint8_t> PresentPass::captured(uint32_t& width, uint32_t& height) const {
    const Impl& m = *m_impl;
    width = m.captured_width;
    height = m.captured_height;
    std::vector<uint8_t> bytes(size_t(width) * height * 4);
    if (!bytes.empty()) std::memcpy(bytes.data(), m.readback.mapped(), bytes.size());
    return bytes;
}

}  // namespace mvpl::preview
