#pragma once
// Internal: the VkInstance, with the validation layer and its messenger when asked for.
#include <vulkan/vulkan.h>

#include <memory>
#include <string>
#include <vector>

#include "engine/gpu/debug_utils.h"
#include "engine/gpu/validation.h"

namespace mvpl::gpu {

class Instance {
public:
    // validation_source says who asked for validation ("MVPL_VALIDATION=1", "the caller"), for
    // the error when the layer is missing; empty: no validation. log receives the messages.
    // extra_extensions: instance extensions a window system needs to present (GLFW's list);
    // a missing one is an error naming it.
    Instance(const std::string& validation_source, ValidationLog* log,
             const std::vector<std::string>& extra_extensions = {});
    ~Instance();
    Instance(const Instance&) = delete;
    Instance& operator=(const Instance&) = delete;

    VkInstance handle() const { return m_instance; }
    bool validation() const { return m_debug_utils != nullptr; }
    const DebugUtils* debug_utils() const { return m_debug_utils.get(); }
    std::vector<VkPhysicalDevice> physical_devices() const;

private:
    VkInstance m_instance = VK_NULL_HANDLE;
    std::unique_ptr<DebugUtils> m_debug_utils;
};

}  // namespace mvpl::gpu
