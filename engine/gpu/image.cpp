#include "engine/gpu/image.h"

#include <vulkan/vulkan.h>

#include <utility>

#include "engine/gpu/buffer.h"
#include "engine/gpu/command_list.h"
#include "engine/gpu/context.h"
#include "engine/gpu/gpu_error.h"
#include "engine/gpu/vk_check.h"
#include "engine/gpu/vk_types.h"

namespace mvpl::gpu {
namespace {

VkImageUsageFlags to_vk_usage(ImageUsage usage) {
    VkImageUsageFlags flags = VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    if (has(usage, ImageUsage::sampled)) flags |= VK_IMAGE_USAGE_SAMPLED_BIT;
    if (has(usage, ImageUsage::storage)) flags |= VK_IMAGE_USAGE_STORAGE_BIT;
    if (has(usage, ImageUsage::color_attachment)) flags |= VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
    if (has(usage, ImageUsage::depth_attachment)) {
        flags |= VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
    }
    return flags;
}

VkImageView create_view(VkDevice device, VkImage image, VkImageViewType type, Format format,
                        uint32_t base_layer, uint32_t layer_count) {
    VkImageViewCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
    info.image = image;
    info.viewType = type;
    info.format = to_vk_format(format);
    info.subresourceRange = {aspect_of(format), 0, 1, base_layer, layer_count};
    VkImageView view = VK_NULL_HANDLE;
    vk_check(vkCreateImageView(device, &info, nullptr, &view), "vkCreateImageView");
    return view;
}

}  // namespace

Image::Image(Context& context, const ImageDesc& desc, std::string_view name)
    : m_context(&context), m_desc(desc), m_name(name.empty() ? "image" : name) {
    const std::string what = "image '" + m_name + "'";
    if (desc.width == 0 || desc.height == 0 || desc.layers == 0) {
        throw GpuError(what + ": zero size (" + std::to_string(desc.width) + "x" +
                       std::to_string(desc.height) + ", " + std::to_string(desc.layers) +
                       " layers)");
    }
    if (desc.cube && (desc.width != desc.height || desc.layers % 6 != 0)) {
        throw GpuError(what + ": a cube-map array needs square faces and 6 layers per cube");
    }
    if (desc.cube && !context.device_info().image_cube_array) {
        throw GpuError(what + ": " + context.device_info().name + " has no cube-map arrays");
    }
    const VkImageCreateFlags flags = desc.cube ? VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT : 0;
    const VkFormat format = to_vk_format(desc.format);
    const VkImageUsageFlags usage = to_vk_usage(desc.usage);

    // Ask first, so that an unsupported combination is an error that names it, not a
    // validation message or a crash in the driver.
    VkImageFormatProperties limits{};
    const VkResult supported = vkGetPhysicalDeviceImageFormatProperties(
        context.physical_device(), format, VK_IMAGE_TYPE_2D, VK_IMAGE_TILING_OPTIMAL, usage, flags,
        &limits);
    if (supported == VK_ERROR_FORMAT_NOT_SUPPORTED) {
        throw GpuError(what + ": " + format_name(desc.format) + " with usage flags " +
                       std::to_string(uint32_t(desc.usage)) + " is not supported by " +
                       context.device_info().name);
    }
    vk_check(supported, "vkGetPhysicalDeviceImageFormatProperties");
    if (desc.width > limits.maxExtent.width || desc.height > limits.maxExtent.height ||
        desc.layers > limits.maxArrayLayers) {
        throw GpuError(what + ": " + std::to_string(desc.width) + "x" +
                       std::to_string(desc.height) + "x" + std::to_string(desc.layers) +
                       " exceeds the device's " + std::to_string(limits.maxExtent.width) + "x" +
                       std::to_string(limits.maxExtent.height) + "x" +
                       std::to_string(limits.maxArrayLayers));
    }

    VkImageCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO;
    info.flags = flags;
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {desc.width, desc.height, 1};
    info.mipLevels = 1;
    info.arrayLayers = desc.layers;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    const VkDevice device = context.device();
    vk_check(vkCreateImage(device, &info, nullptr, &m_image), "vkCreateImage(" + m_name + ")");
    try {
        VkMemoryRequirements requirements{};
        vkGetImageMemoryRequirements(device, m_image, &requirements);
        m_allocation = context.allocator().allocate(requirements.size, requirements.memoryTypeBits,
                                                    MemoryLocation::device, m_name);
        vk_check(vkBindImageMemory(device, m_image, m_allocation.memory, 0),
                 "vkBindImageMemory(" + m_name + ")");
        const VkImageViewType type = desc.cube         ? VK_IMAGE_VIEW_TYPE_CUBE_ARRAY
                                     : desc.layers > 1 ? VK_IMAGE_VIEW_TYPE_2D_ARRAY
                                                       : VK_IMAGE_VIEW_TYPE_2D;
        m_view = create_view(device, m_image, type, desc.format, 0, desc.layers);
        if (has(desc.usage, ImageUsage::color_attachment) ||
            has(desc.usage, ImageUsage::depth_attachment)) {
            for (uint32_t layer = 0; layer < desc.layers; ++layer) {
                m_layer_views.push_back(
                    create_view(device, m_image, VK_IMAGE_VIEW_TYPE_2D, desc.format, layer, 1));
            }
        }
        context.set_debug_name(VK_OBJECT_TYPE_IMAGE, uint64_t(m_image), m_name);
        context.submit_and_wait([&](CommandList& cmd) { cmd.initialize_layout(*this); });
    } catch (...) {
        release();
        throw;
    }
}

Image::~Image() {
    release();
}

Image::Image(Image&& other) noexcept {
    *this = std::move(other);
}

Image& Image::operator=(Image&& other) noexcept {
    if (this != &other) {
        release();
        m_context = std::exchange(other.m_context, nullptr);
        m_desc = other.m_desc;
        m_name = std::move(other.m_name);
        m_image = std::exchange(other.m_image, nullptr);
        m_view = std::exchange(other.m_view, nullptr);
        m_layer_views = std::move(other.m_layer_views);
        other.m_layer_views.clear();
        m_allocation = std::exchange(other.m_allocation, Allocation{});
    }
    return *this;
}

void Image::release() noexcept {
    if (!m_context) return;
    const VkDevice device = m_context->device();
    for (VkImageView view : m_layer_views)
        vkDestroyImageView(device, view, nullptr);
    m_layer_views.clear();
    if (m_view) vkDestroyImageView(device, m_view, nullptr);
    if (m_image) vkDestroyImage(device, m_image, nullptr);
    m_context->allocator().free(m_allocation);
    m_view = nullptr;
    m_image = nullptr;
    m_context = nullptr;
}

uint64_t Image::layer_bytes() const {
    return uint64_t(m_desc.width) * m_desc.height * bytes_per_pixel(m_desc.format);
}

VkImageView Image::layer_view(uint32_t layer) const {
    return layer < m_layer_views.size() ? m_layer_views[layer] : nullptr;
}

void Image::check_layers(uint32_t base_layer, uint32_t layer_count) const {
    if (!valid()) throw GpuError("transfer on an empty Image");
    if (layer_count == 0 || base_layer >= m_desc.layers ||
        layer_count > m_desc.layers - base_layer) {
        throw GpuError("image '" + m_name + "': layers [" + std::to_string(base_layer) + ", " +
                       std::to_string(uint64_t(base_layer) + layer_count) + ") outside its " +
                       std::to_string(m_desc.layers));
    }
}

void Image::upload(std::span<const std::byte> pixels, uint32_t base_layer, uint32_t layer_count) {
    check_layers(base_layer, layer_count);
    Buffer staging(*m_context, layer_bytes() * layer_count, BufferUsage::none,
                   MemoryLocation::upload, m_name + " (staging)");
    upload(pixels, staging, base_layer, layer_count);
}

void Image::upload(std::span<const std::byte> pixels, Buffer& staging, uint32_t base_layer,
                   uint32_t layer_count) {
    check_layers(base_layer, layer_count);
    const uint64_t bytes = layer_bytes() * layer_count;
    if (pixels.size() != bytes || staging.size() < bytes) {
        throw GpuError("image '" + m_name + "': upload of " + std::to_string(pixels.size()) +
                       " bytes through a buffer of " + std::to_string(staging.size()) +
                       ", expected " + std::to_string(bytes));
    }
    std::memcpy(staging.mapped(), pixels.data(), bytes);
    m_context->submit_and_wait([&](CommandList& cmd) {
        cmd.copy_buffer_to_image(staging, *this, base_layer, layer_count);
    });
}

std::vector<std::byte> Image::download(uint32_t base_layer, uint32_t layer_count) const {
    check_layers(base_layer, layer_count);
    const uint64_t bytes = layer_bytes() * layer_count;
    Buffer staging(*m_context, bytes, BufferUsage::none, MemoryLocation::readback,
                   m_name + " (readback)");
    m_context->submit_and_wait([&](CommandList& cmd) {
        cmd.copy_image_to_buffer(*this, staging, base_layer, layer_count);
    });
    return std::vector<std::byte>(staging.mapped(), staging.mapped() + bytes);
}

}  // namespace mvpl::gpu
