#include "engine/gpu/validation.h"

#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "engine/gpu/debug_utils.h"
#include "engine/gpu/gpu_error.h"
#include "engine/gpu/vk_check.h"

namespace mvpl::gpu {

bool validation_requested_by_environment() {
    const char* value = std::getenv("MVPL_VALIDATION");
    if (!value) return false;
    const std::string v(value);
    return v == "1" || v == "true" || v == "on" || v == "yes" || v == "TRUE" || v == "ON";
}

bool validation_layer_available() {
    uint32_t count = 0;
    if (vkEnumerateInstanceLayerProperties(&count, nullptr) != VK_SUCCESS) return false;
    std::vector<VkLayerProperties> layers(count);
    if (vkEnumerateInstanceLayerProperties(&count, layers.data()) < 0) return false;
    for (const VkLayerProperties& layer : layers) {
        if (std::strcmp(layer.layerName, kValidationLayerName) == 0) return true;
    }
    return false;
}

void ValidationLog::add(std::string message) {
    std::lock_guard lock(m_mutex);
    m_messages.push_back(std::move(message));
}

size_t ValidationLog::count() const {
    std::lock_guard lock(m_mutex);
    return m_messages.size();
}

std::vector<std::string> ValidationLog::messages() const {
    std::lock_guard lock(m_mutex);
    return m_messages;
}

void ValidationLog::clear() {
    std::lock_guard lock(m_mutex);
    m_messages.clear();
}

std::string ValidationLog::summary(size_t max_messages) const {
    std::lock_guard lock(m_mutex);
    std::string text;
    for (size_t i = 0; i < m_messages.size() && i < max_messages; ++i)
        text += m_messages[i] + "\n";
    if (m_messages.size() > max_messages) {
        text += "… and " + std::to_string(m_messages.size() - max_messages) + " more\n";
    }
    return text;
}

namespace {

VKAPI_ATTR VkBool32 VKAPI_CALL on_debug_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                VkDebugUtilsMessageTypeFlagsEXT types,
                                                const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                void* user) {
    const char* kind = (types & VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT)    ? "validation"
                       : (types & VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT) ? "performance"
                                                                                   : "general";
    const char* level =
        (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) ? "error" : "warning";
    std::string line = std::string("[") + kind + " " + level + "] ";
    if (data->pMessageIdName) line += std::string(data->pMessageIdName) + ": ";
    if (data->pMessage) line += data->pMessage;
    static_cast<ValidationLog*>(user)->add(std::move(line));
    // VK_FALSE: the call that triggered the message goes on as if there were no layer.
    return VK_FALSE;
}

}  // namespace

VkDebugUtilsMessengerCreateInfoEXT debug_messenger_info(ValidationLog* log) {
    VkDebugUtilsMessengerCreateInfoEXT info{};
    info.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT;
    // Info and verbose are the loader's and layer's chatter, not findings: not asked for.
    info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                           VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    info.pfnUserCallback = on_debug_message;
    info.pUserData = log;
    return info;
}

DebugUtils::DebugUtils(VkInstance instance, ValidationLog* log) : m_instance(instance) {
    // Extension entry points are not exported by the loader library: fetch them.
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
    m_destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
    m_set_name = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
        vkGetInstanceProcAddr(instance, "vkSetDebugUtilsObjectNameEXT"));
    if (!create || !m_destroy) throw GpuError("VK_EXT_debug_utils is enabled but not callable");
    const VkDebugUtilsMessengerCreateInfoEXT info = debug_messenger_info(log);
    vk_check(create(instance, &info, nullptr, &m_messenger), "vkCreateDebugUtilsMessengerEXT");
}

DebugUtils::~DebugUtils() {
    if (m_messenger) m_destroy(m_instance, m_messenger, nullptr);
}

void DebugUtils::set_name(VkDevice device, VkObjectType type, uint64_t handle,
                          std::string_view name) const {
    if (!m_set_name || name.empty() || handle == 0) return;
    const std::string text(name);
    VkDebugUtilsObjectNameInfoEXT info{};
    info.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT;
    info.objectType = type;
    info.objectHandle = handle;
    info.pObjectName = text.c_str();
    m_set_name(device, &info);
}

}  // namespace mvpl::gpu
