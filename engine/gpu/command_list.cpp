#include "engine/gpu/command_list.h"

#include <vulkan/vulkan.h>

#include <string>
#include <vector>

#include "engine/gpu/buffer.h"
#include "engine/gpu/compute_pipeline.h"
#include "engine/gpu/context.h"
#include "engine/gpu/gpu_error.h"
#include "engine/gpu/image.h"
#include "engine/gpu/vk_types.h"

namespace mvpl::gpu {
namespace {

VkImageSubresourceRange layer_range(const Image& image, uint32_t base_layer, uint32_t count) {
    if (count == 0) count = image.layers() > base_layer ? image.layers() - base_layer : 0;
    if (count == 0 || base_layer + uint64_t(count) > image.layers()) {
        throw GpuError("image '" + image.name() + "': layers [" + std::to_string(base_layer) +
                       ", +" + std::to_string(count) + ") outside its " +
                       std::to_string(image.layers()));
    }
    return {aspect_of(image.format()), 0, 1, base_layer, count};
}

VkBufferImageCopy layers_copy(const Image& image, uint32_t base_layer, uint32_t layer_count) {
    const VkImageSubresourceRange range = layer_range(image, base_layer, layer_count);
    VkBufferImageCopy copy{};
    copy.bufferOffset = 0;
    copy.bufferRowLength = 0;  // 0: tightly packed
    copy.bufferImageHeight = 0;
    copy.imageSubresource = {range.aspectMask, 0, range.baseArrayLayer, range.layerCount};
    copy.imageExtent = {image.width(), image.height(), 1};
    return copy;
}

// Copies run in the transfer-optimal layouts (the layer warns about GENERAL there, and some GPUs
// copy faster); the image returns to GENERAL right after, so callers never see the difference.
void transition(VkCommandBuffer cmd, const Image& image, const VkImageSubresourceRange& range,
                VkImageLayout from, VkImageLayout to, VkAccessFlags2 src_access,
                VkAccessFlags2 dst_access) {
    VkImageMemoryBarrier2 barrier{};
    barrier.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2;
    barrier.srcStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    barrier.srcAccessMask = src_access;
    barrier.dstStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    barrier.dstAccessMask = dst_access;
    barrier.oldLayout = from;
    barrier.newLayout = to;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = image.handle();
    barrier.subresourceRange = range;
    VkDependencyInfo dependency{};
    dependency.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO;
    dependency.imageMemoryBarrierCount = 1;
    dependency.pImageMemoryBarriers = &barrier;
    vkCmdPipelineBarrier2(cmd, &dependency);
}

VkImageSubresourceRange copied_range(const Image& image, const VkBufferImageCopy& copy) {
    return {aspect_of(image.format()), 0, 1, copy.imageSubresource.baseArrayLayer,
            copy.imageSubresource.layerCount};
}

constexpr VkAccessFlags2 kAnyAccess = VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT;

void require_bytes(const Buffer& buffer, uint64_t bytes, const char* what) {
    if (buffer.size() < bytes) {
        throw GpuError(std::string(what) + ": buffer '" + buffer.name() + "' holds " +
                       std::to_string(buffer.size()) + " bytes, the copy needs " +
                       std::to_string(bytes));
    }
}

}  // namespace

void CommandList::barrier() {
    VkMemoryBarrier2 barrier{};
    barrier.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER_2;
    barrier.srcStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    barrier.srcAccessMask = VK_ACCESS_2_MEMORY_WRITE_BIT;
    barrier.dstStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    barrier.dstAccessMask = VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT;
    VkDependencyInfo dependency{};
    dependency.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO;
    dependency.memoryBarrierCount = 1;
    dependency.pMemoryBarriers = &barrier;
    vkCmdPipelineBarrier2(m_cmd, &dependency);
}

void CommandList::copy_buffer(const Buffer& src, Buffer& dst, uint64_t bytes, uint64_t src_offset,
                              uint64_t dst_offset) {
    if (src_offset + bytes > src.size() || dst_offset + bytes > dst.size()) {
        throw GpuError("copy of " + std::to_string(bytes) + " bytes from '" + src.name() +
                       "' to '" + dst.name() + "' runs past a buffer's end");
    }
    const VkBufferCopy region{src_offset, dst_offset, bytes};
    vkCmdCopyBuffer(m_cmd, src.handle(), dst.handle(), 1, &region);
}

void CommandList::copy_buffer_to_image(const Buffer& src, Image& dst, uint32_t base_layer,
                                       uint32_t layer_count) {
    const VkBufferImageCopy copy = layers_copy(dst, base_layer, layer_count);
    require_bytes(src, dst.layer_bytes() * copy.imageSubresource.layerCount,
                  "copy_buffer_to_image");
    const VkImageSubresourceRange range = copied_range(dst, copy);
    transition(m_cmd, dst, range, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
               VK_ACCESS_2_MEMORY_WRITE_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
    vkCmdCopyBufferToImage(m_cmd, src.handle(), dst.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                           1, &copy);
    transition(m_cmd, dst, range, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
               VK_ACCESS_2_TRANSFER_WRITE_BIT, kAnyAccess);
}

void CommandList::copy_image_to_buffer(const Image& src, Buffer& dst, uint32_t base_layer,
                                       uint32_t layer_count) {
    const VkBufferImageCopy copy = layers_copy(src, base_layer, layer_count);
    require_bytes(dst, src.layer_bytes() * copy.imageSubresource.layerCount,
                  "copy_image_to_buffer");
    const VkImageSubresourceRange range = copied_range(src, copy);
    transition(m_cmd, src, range, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
               VK_ACCESS_2_MEMORY_WRITE_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
    vkCmdCopyImageToBuffer(m_cmd, src.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, dst.handle(),
                           1, &copy);
    // A read: later writers only have to wait for it to finish (no access to make available).
    transition(m_cmd, src, range, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
               VK_ACCESS_2_NONE, kAnyAccess);
}

void CommandList::copy_image_layers(const Image& src, Image& dst,
                                    std::span<const LayerCopy> copies) {
    if (copies.empty()) return;
    if (&src == &dst || src.width() != dst.width() || src.height() != dst.height() ||
        src.format() != dst.format()) {
        throw GpuError("copy_image_layers from '" + src.name() + "' to '" + dst.name() +
                       "': distinct images of one size and format");
    }
    std::vector<VkImageCopy> regions;
    regions.reserve(copies.size());
    for (const LayerCopy& c : copies) {
        const VkImageSubresourceRange from = layer_range(src, c.src_layer, c.count);
        const VkImageSubresourceRange to = layer_range(dst, c.dst_layer, c.count);
        VkImageCopy region{};
        region.srcSubresource = {from.aspectMask, 0, from.baseArrayLayer, from.layerCount};
        region.dstSubresource = {to.aspectMask, 0, to.baseArrayLayer, to.layerCount};
        region.extent = {src.width(), src.height(), 1};
        regions.push_back(region);
    }
    const VkImageSubresourceRange all_src = layer_range(src, 0, 0);
    const VkImageSubresourceRange all_dst = layer_range(dst, 0, 0);
    transition(m_cmd, src, all_src, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
               VK_ACCESS_2_MEMORY_WRITE_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
    transition(m_cmd, dst, all_dst, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
               VK_ACCESS_2_MEMORY_WRITE_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
    vkCmdCopyImage(m_cmd, src.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, dst.handle(),
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, uint32_t(regions.size()), regions.data());
    transition(m_cmd, src, all_src, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
               VK_ACCESS_2_NONE, kAnyAccess);
    transition(m_cmd, dst, all_dst, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
               VK_ACCESS_2_TRANSFER_WRITE_BIT, kAnyAccess);
}

void CommandList::clear_color(Image& image, const std::array<float, 4>& rgba, uint32_t base_layer,
                              uint32_t layer_count) {
    if (is_depth(image.format()))
        throw GpuError("clear_color on depth image '" + image.name() + "'");
    const VkImageSubresourceRange range = layer_range(image, base_layer, layer_count);
    VkClearColorValue value{};
    // An integer image takes the value as uint32 bits; the float bits would be garbage.
    if (image.format() == Format::r32_uint) {
        for (int i = 0; i < 4; ++i)
            value.uint32[i] = uint32_t(rgba[size_t(i)]);
    } else {
        for (int i = 0; i < 4; ++i)
            value.float32[i] = rgba[size_t(i)];
    }
    vkCmdClearColorImage(m_cmd, image.handle(), VK_IMAGE_LAYOUT_GENERAL, &value, 1, &range);
}

void CommandList::clear_depth(Image& image, float depth, uint32_t base_layer,
                              uint32_t layer_count) {
    if (!is_depth(image.format()))
        throw GpuError("clear_depth on colour image '" + image.name() + "'");
    const VkImageSubresourceRange range = layer_range(image, base_layer, layer_count);
    const VkClearDepthStencilValue value{depth, 0};
    vkCmdClearDepthStencilImage(m_cmd, image.handle(), VK_IMAGE_LAYOUT_GENERAL, &value, 1, &range);
}

void CommandList::initialize_layout(const Image& image) {
    VkImageMemoryBarrier2 barrier{};
    barrier.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2;
    barrier.srcStageMask = VK_PIPELINE_STAGE_2_NONE;
    barrier.dstStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    barrier.dstAccessMask = VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT;
    barrier.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    barrier.newLayout = VK_IMAGE_LAYOUT_GENERAL;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = image.handle();
    barrier.subresourceRange = layer_range(image, 0, 0);
    VkDependencyInfo dependency{};
    dependency.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO;
    dependency.imageMemoryBarrierCount = 1;
    dependency.pImageMemoryBarriers = &barrier;
    vkCmdPipelineBarrier2(m_cmd, &dependency);
}

void CommandList::dispatch(const ComputePipeline& pipeline, std::span<const Resource> resources,
                           std::span<const std::byte> push_constants, uint32_t groups_x,
                           uint32_t groups_y, uint32_t groups_z) {
    const ComputeLayout& layout = pipeline.layout();
    const std::string what = "dispatch of '" + pipeline.name() + "'";
    if (resources.size() != layout.bindings.size()) {
        throw GpuError(what + ": " + std::to_string(resources.size()) + " resources for " +
                       std::to_string(layout.bindings.size()) + " bindings");
    }
    if (push_constants.size() != layout.push_constant_bytes) {
        throw GpuError(what + ": " + std::to_string(push_constants.size()) +
                       " push-constant bytes, the layout has " +
                       std::to_string(layout.push_constant_bytes));
    }

    // Reserved up front: the writes point into these vectors.
    std::vector<VkDescriptorBufferInfo> buffer_infos;
    std::vector<VkDescriptorImageInfo> image_infos;
    buffer_infos.reserve(resources.size());
    image_infos.reserve(resources.size());
    std::vector<VkWriteDescriptorSet> writes;
    VkDescriptorSet set = VK_NULL_HANDLE;
    if (!resources.empty()) set = m_context->allocate_transient_set(pipeline.set_layout());
    for (uint32_t i = 0; i < resources.size(); ++i) {
        const BindingType type = layout.bindings[i];
        const bool wants_buffer =
            type == BindingType::storage_buffer || type == BindingType::uniform_buffer;
        VkWriteDescriptorSet write{};
        write.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
        write.dstSet = set;
        write.dstBinding = i;
        write.descriptorCount = 1;
        write.descriptorType = to_vk_descriptor_type(type);
        if (wants_buffer) {
            const Buffer* const* buffer = std::get_if<const Buffer*>(&resources[i]);
            if (!buffer || !*buffer)
                throw GpuError(what + ": binding " + std::to_string(i) + " needs a buffer");
            buffer_infos.push_back({(*buffer)->handle(), 0, VK_WHOLE_SIZE});
            write.pBufferInfo = &buffer_infos.back();
        } else {
            const Image* const* image = std::get_if<const Image*>(&resources[i]);
            if (!image || !*image)
                throw GpuError(what + ": binding " + std::to_string(i) + " needs an image");
            // The sampler of a sampled image is immutable in the set layout.
            image_infos.push_back({VK_NULL_HANDLE, (*image)->view(), VK_IMAGE_LAYOUT_GENERAL});
            write.pImageInfo = &image_infos.back();
        }
        writes.push_back(write);
    }
    if (!writes.empty()) {
        vkUpdateDescriptorSets(m_context->device(), uint32_t(writes.size()), writes.data(), 0,
                               nullptr);
    }

    vkCmdBindPipeline(m_cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.handle());
    if (set) {
        vkCmdBindDescriptorSets(m_cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.pipeline_layout(),
                                0, 1, &set, 0, nullptr);
    }
    if (!push_constants.empty()) {
        vkCmdPushConstants(m_cmd, pipeline.pipeline_layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0,
                           uint32_t(push_constants.size()), push_constants.data());
    }
    vkCmdDispatch(m_cmd, groups_x, groups_y, groups_z);
}

}  // namespace mvpl::gpu
