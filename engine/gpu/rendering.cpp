#include "engine/gpu/rendering.h"

#include <vulkan/vulkan.h>

#include <string>
#include <vector>

#include "engine/gpu/command_list.h"
#include "engine/gpu/gpu_error.h"
#include "engine/gpu/image.h"

namespace mvpl::gpu {

void begin_rendering(CommandList& cmd, std::span<const ColorTarget> colors,
                     const DepthTarget* depth, const RenderArea* area) {
    const Image* first = !colors.empty() ? colors[0].image : depth ? depth->image : nullptr;
    if (!first) throw GpuError("begin_rendering without targets");
    const uint32_t width = first->width();
    const uint32_t height = first->height();
    std::vector<VkRenderingAttachmentInfo> attachments;
    for (const ColorTarget& target : colors) {
        const VkImageView view = target.image ? target.image->layer_view(target.layer) : nullptr;
        if (!view || target.image->width() != width || target.image->height() != height) {
            throw GpuError("begin_rendering: colour target '" +
                           (target.image ? target.image->name() : std::string("null")) +
                           "' layer " + std::to_string(target.layer) +
                           " is not an attachment of the common size");
        }
        VkRenderingAttachmentInfo a{};
        a.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO;
        a.imageView = view;
        a.imageLayout = VK_IMAGE_LAYOUT_GENERAL;
        a.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        for (int i = 0; i < 4; ++i)
            a.clearValue.color.float32[i] = target.clear[size_t(i)];
        attachments.push_back(a);
    }
    VkRenderingAttachmentInfo depth_attachment{};
    if (depth) {
        const VkImageView view = depth->image ? depth->image->layer_view(depth->layer) : nullptr;
        if (!view || depth->image->width() != width || depth->image->height() != height) {
            throw GpuError("begin_rendering: the depth target is not an attachment of the size");
        }
        depth_attachment.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO;
        depth_attachment.imageView = view;
        depth_attachment.imageLayout = VK_IMAGE_LAYOUT_GENERAL;
        depth_attachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        // The depth is only needed while drawing: nothing reads it afterwards.
        depth_attachment.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
        depth_attachment.clearValue.depthStencil = {depth->clear, 0};
    }
    VkRenderingInfo info{};
    info.sType = VK_STRUCTURE_TYPE_RENDERING_INFO;
    VkRect2D scissor{{0, 0}, {width, height}};
    if (area) {
        if (area->width == 0 || area->height == 0 || area->x + area->width > width ||
            area->y + area->height > height) {
            throw GpuError("begin_rendering: the render area is empty or outside the targets");
        }
        scissor = {{int32_t(area->x), int32_t(area->y)}, {area->width, area->height}};
    }
    info.renderArea = scissor;
    info.layerCount = 1;
    info.colorAttachmentCount = uint32_t(attachments.size());
    info.pColorAttachments = attachments.data();
    info.pDepthAttachment = depth ? &depth_attachment : nullptr;
    vkCmdBeginRendering(cmd.handle(), &info);
    const VkViewport viewport{0.0f, 0.0f, float(width), float(height), 0.0f, 1.0f};
    vkCmdSetViewport(cmd.handle(), 0, 1, &viewport);
    vkCmdSetScissor(cmd.handle(), 0, 1, &scissor);
}

void end_rendering(CommandList& cmd) {
    vkCmdEndRendering(cmd.handle());
}

}  // namespace mvpl::gpu
