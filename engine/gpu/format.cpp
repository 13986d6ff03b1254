#include "engine/gpu/format.h"

#include "engine/gpu/vk_types.h"

namespace mvpl::gpu {

uint32_t bytes_per_pixel(Format format) {
    switch (format) {
        case Format::r32_float:
        case Format::r32_uint:
        case Format::d32_float:
        case Format::rgba8_unorm:
        case Format::rgba8_srgb:
            return 4;
        case Format::rg32_float:
        case Format::rgba16_float:
            return 8;
        case Format::rgba32_float:
            return 16;
    }
    return 0;
}

bool is_depth(Format format) {
    return format == Format::d32_float;
}

const char* format_name(Format format) {
    switch (format) {
        case Format::r32_float:
            return "r32_float";
        case Format::rg32_float:
            return "rg32_float";
        case Format::rgba32_float:
            return "rgba32_float";
        case Format::rgba16_float:
            return "rgba16_float";
        case Format::rgba8_unorm:
            return "rgba8_unorm";
        case Format::rgba8_srgb:
            return "rgba8_srgb";
        case Format::r32_uint:
            return "r32_uint";
        case Format::d32_float:
            return "d32_float";
    }
    return "?";
}

VkFormat to_vk_format(Format format) {
    switch (format) {
        case Format::r32_float:
            return VK_FORMAT_R32_SFLOAT;
        case Format::rg32_float:
            return VK_FORMAT_R32G32_SFLOAT;
        case Format::rgba32_float:
            return VK_FORMAT_R32G32B32A32_SFLOAT;
        case Format::rgba16_float:
            return VK_FORMAT_R16G16B16A16_SFLOAT;
        case Format::rgba8_unorm:
            return VK_FORMAT_R8G8B8A8_UNORM;
        case Format::rgba8_srgb:
            return VK_FORMAT_R8G8B8A8_SRGB;
        case Format::r32_uint:
            return VK_FORMAT_R32_UINT;
        case Format::d32_float:
            return VK_FORMAT_D32_SFLOAT;
    }
    return VK_FORMAT_UNDEFINED;
}

VkImageAspectFlags aspect_of(Format format) {
    return is_depth(format) ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
}

}  // namespace mvpl::gpu
