#pragma once
// Pixel formats mvpl uses, without VkFormat in the interface.
#include <cstdint>

namespace mvpl::gpu {

enum class Format {
    r32_float,
    rg32_float,    // shadow texels: distance (blendable, unlike D32 on lavapipe) and plane
    rgba32_float,  // accumulation, G-buffer
    rgba16_float,
    rgba8_unorm,
    rgba8_srgb,
    r32_uint,   // closure ids
    d32_float,  // depth attachments
};

uint32_t bytes_per_pixel(Format format);
bool is_depth(Format format);
// "rgba32_float"
const char* format_name(Format format);

}  // namespace mvpl::gpu
