#include "engine/gpu/vk_check.h"

#include <string>
#include <type_traits>

#include "engine/gpu/gpu_error.h"
#include "engine/gpu/vk_fwd.h"

// vk_fwd.h repeats the handle typedefs; these fail on a target where they would differ.
static_assert(std::is_same_v<VkBuffer, VkBuffer_T*>, "vk_fwd.h needs 64-bit Vulkan handles");
static_assert(std::is_same_v<VkImage, VkImage_T*>, "vk_fwd.h needs 64-bit Vulkan handles");

namespace mvpl::gpu {

const char* vk_result_name(VkResult result) {
    switch (result) {
#define MVPL_VK_RESULT(name) \
    case name:               \
        return #name;
        MVPL_VK_RESULT(VK_SUCCESS)
        MVPL_VK_RESULT(VK_NOT_READY)
        MVPL_VK_RESULT(VK_TIMEOUT)
        MVPL_VK_RESULT(VK_EVENT_SET)
        MVPL_VK_RESULT(VK_EVENT_RESET)
        MVPL_VK_RESULT(VK_INCOMPLETE)
        MVPL_VK_RESULT(VK_ERROR_OUT_OF_HOST_MEMORY)
        MVPL_VK_RESULT(VK_ERROR_OUT_OF_DEVICE_MEMORY)
        MVPL_VK_RESULT(VK_ERROR_INITIALIZATION_FAILED)
        MVPL_VK_RESULT(VK_ERROR_DEVICE_LOST)
        MVPL_VK_RESULT(VK_ERROR_MEMORY_MAP_FAILED)
        MVPL_VK_RESULT(VK_ERROR_LAYER_NOT_PRESENT)
        MVPL_VK_RESULT(VK_ERROR_EXTENSION_NOT_PRESENT)
        MVPL_VK_RESULT(VK_ERROR_FEATURE_NOT_PRESENT)
        MVPL_VK_RESULT(VK_ERROR_INCOMPATIBLE_DRIVER)
        MVPL_VK_RESULT(VK_ERROR_TOO_MANY_OBJECTS)
        MVPL_VK_RESULT(VK_ERROR_FORMAT_NOT_SUPPORTED)
        MVPL_VK_RESULT(VK_ERROR_FRAGMENTED_POOL)
        MVPL_VK_RESULT(VK_ERROR_UNKNOWN)
        MVPL_VK_RESULT(VK_ERROR_OUT_OF_POOL_MEMORY)
        MVPL_VK_RESULT(VK_ERROR_INVALID_EXTERNAL_HANDLE)
        MVPL_VK_RESULT(VK_ERROR_FRAGMENTATION)
        MVPL_VK_RESULT(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS)
        MVPL_VK_RESULT(VK_PIPELINE_COMPILE_REQUIRED)
        MVPL_VK_RESULT(VK_ERROR_SURFACE_LOST_KHR)
        MVPL_VK_RESULT(VK_ERROR_NATIVE_WINDOW_IN_USE_KHR)
        MVPL_VK_RESULT(VK_SUBOPTIMAL_KHR)
        MVPL_VK_RESULT(VK_ERROR_OUT_OF_DATE_KHR)
        MVPL_VK_RESULT(VK_ERROR_VALIDATION_FAILED_EXT)
#undef MVPL_VK_RESULT
        default:
            return nullptr;
    }
}

VkResult vk_check(VkResult result, std::string_view what) {
    if (result >= 0) return result;
    const char* name = vk_result_name(result);
    throw GpuError(std::string(what) + " failed: " +
                   (name ? std::string(name) : "VkResult " + std::to_string(int(result))));
}

}  // namespace mvpl::gpu
