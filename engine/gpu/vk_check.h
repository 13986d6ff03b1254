#pragma once
// Internal to engine/gpu and the render passes: includes <vulkan/vulkan.h>.
#include <vulkan/vulkan.h>

#include <string_view>

namespace mvpl::gpu {

// "VK_ERROR_OUT_OF_DEVICE_MEMORY" etc.; nullptr for codes newer than this list.
const char* vk_result_name(VkResult result);

// Throws GpuError("WHAT failed: VK_ERROR_…") for an error code. Positive codes (VK_INCOMPLETE,
// VK_NOT_READY, …) are not errors and are returned so that the caller can look at them.
VkResult vk_check(VkResult result, std::string_view what);

}  // namespace mvpl::gpu
