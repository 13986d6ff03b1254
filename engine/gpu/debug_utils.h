#pragma once
// Internal: VK_EXT_debug_utils, the channel through which the validation layer reports into a
// ValidationLog, and object names that make its messages readable. Includes <vulkan/vulkan.h>.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <string_view>

#include "engine/gpu/validation.h"

namespace mvpl::gpu {

// The messenger description: warnings and errors of every type, into log. Chained into
// VkInstanceCreateInfo as well, so that instance creation and destruction are covered too.
VkDebugUtilsMessengerCreateInfoEXT debug_messenger_info(ValidationLog* log);

class DebugUtils {
public:
    DebugUtils(VkInstance instance, ValidationLog* log);
    ~DebugUtils();
    DebugUtils(const DebugUtils&) = delete;
    DebugUtils& operator=(const DebugUtils&) = delete;

    // Names a Vulkan object in validation messages (and in RenderDoc and friends).
    void set_name(VkDevice device, VkObjectType type, uint64_t handle, std::string_view name) const;

private:
    VkInstance m_instance = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT m_messenger = VK_NULL_HANDLE;
    PFN_vkDestroyDebugUtilsMessengerEXT m_destroy = nullptr;
    PFN_vkSetDebugUtilsObjectNameEXT m_set_name = nullptr;
};

}  // namespace mvpl::gpu
