#include "engine/gpu/instance.h"

#include <cstring>

#include "engine/gpu/gpu_error.h"
#include "engine/gpu/vk_check.h"

namespace mvpl::gpu {
namespace {

bool has_extension(const std::vector<VkExtensionProperties>& list, const char* name) {
    for (const VkExtensionProperties& e : list) {
        if (std::strcmp(e.extensionName, name) == 0) return true;
    }
    return false;
}

std::vector<VkExtensionProperties> instance_extensions(const char* layer) {
    uint32_t count = 0;
    vk_check(vkEnumerateInstanceExtensionProperties(layer, &count, nullptr),
             "vkEnumerateInstanceExtensionProperties");
    std::vector<VkExtensionProperties> list(count);
    vk_check(vkEnumerateInstanceExtensionProperties(layer, &count, list.data()),
             "vkEnumerateInstanceExtensionProperties");
    list.resize(count);
    return list;
}

// The layers, extensions and flags of the instance.
struct InstanceRequest {
    std::vector<const char*> extensions;
    std::vector<const char*> layers;
    VkInstanceCreateFlags flags = 0;
    bool validation_features = false;  // VK_EXT_validation_features enabled
};

// The layer and extensions that validation needs (the validation layer present).
void request_validation(const std::vector<VkExtensionProperties>& available,
                        InstanceRequest& request) {
    request.layers.push_back(kValidationLayerName);
    // The layer implements debug_utils itself when the loader's list lacks it.
    if (!has_extension(available, VK_EXT_DEBUG_UTILS_EXTENSION_NAME) &&
        !has_extension(instance_extensions(kValidationLayerName),
                       VK_EXT_DEBUG_UTILS_EXTENSION_NAME)) {
        throw GpuError(
            "Vulkan validation needs VK_EXT_debug_utils, which neither the loader "
            "nor the validation layer provides");
    }
    request.extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    // The layer provides it; it makes the VkValidationFeaturesEXT below legal to chain.
    if (has_extension(instance_extensions(kValidationLayerName),
                      VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME)) {
        request.extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
        request.validation_features = true;
    }
}

// What the instance enables; extra_extensions must outlive it (it points to their names).
InstanceRequest instance_request(bool validation,
                                 const std::vector<std::string>& extra_extensions) {
    InstanceRequest request;
    const std::vector<VkExtensionProperties> available = instance_extensions(nullptr);
    // MoltenVK and other non-conformant drivers are listed only when we say we can cope.
    if (has_extension(available, VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME)) {
        request.extensions.push_back(VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME);
        request.flags |= VK_INSTANCE_CREATE_ENUMERATE_PORTABILITY_BIT_KHR;
    }
    for (const std::string& name : extra_extensions) {
        if (!has_extension(available, name.c_str())) {
            throw GpuError("the Vulkan loader lacks the instance extension " + name +
                           ", which presenting to a window needs");
        }
        request.extensions.push_back(name.c_str());
    }
    if (validation) request_validation(available, request);
    return request;
}

VkApplicationInfo application_info() {
    VkApplicationInfo app{};
    app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
    app.pApplicationName = "mvpl";
    app.applicationVersion = VK_MAKE_API_VERSION(0, 0, 1, 0);
    app.pEngineName = "mvpl";
    app.engineVersion = VK_MAKE_API_VERSION(0, 0, 1, 0);
    app.apiVersion = VK_API_VERSION_1_3;
    return app;
}

}  // namespace

Instance::Instance(const std::string& validation_source, ValidationLog* log,
                   const std::vector<std::string>& extra_extensions) {
    const bool validation = !validation_source.empty();
    if (validation && !validation_layer_available()) {
        throw GpuError(validation_source + " asks for Vulkan validation, but the layer " +
                       kValidationLayerName +
                       " is not installed (Debian/Ubuntu: apt install vulkan-validationlayers; "
                       "or set VK_LAYER_PATH to its directory)");
    }
    const InstanceRequest request = instance_request(validation, extra_extensions);
    VkDebugUtilsMessengerCreateInfoEXT messenger_info{};
    if (validation) messenger_info = debug_messenger_info(log);
    const VkApplicationInfo app = application_info();

    // Synchronisation validation on top of the default checks: the passes' barriers are the
    // part that lavapipe (which executes in order) can never show to be wrong.
    const VkValidationFeatureEnableEXT enables[] = {
        VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
    VkValidationFeaturesEXT features{};
    features.sType = VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT;
    features.pNext = &messenger_info;
    features.enabledValidationFeatureCount = 1;
    features.pEnabledValidationFeatures = enables;

    VkInstanceCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
    // Chained messenger: reports problems in vkCreateInstance/vkDestroyInstance themselves.
    info.pNext = request.validation_features ? static_cast<const void*>(&features)
                 : validation                ? static_cast<const void*>(&messenger_info)
                                             : nullptr;
    info.flags = request.flags;
    info.pApplicationInfo = &app;
    info.enabledLayerCount = uint32_t(request.layers.size());
    info.ppEnabledLayerNames = request.layers.data();
    info.enabledExtensionCount = uint32_t(request.extensions.size());
    info.ppEnabledExtensionNames = request.extensions.data();
    const VkResult result = vkCreateInstance(&info, nullptr, &m_instance);
    if (result == VK_ERROR_INCOMPATIBLE_DRIVER) {
        throw GpuError(
            "no Vulkan driver found (vkCreateInstance: VK_ERROR_INCOMPATIBLE_DRIVER); "
            "for the software rasteriser install mesa-vulkan-drivers (lavapipe)");
    }
    vk_check(result, "vkCreateInstance");
    if (validation) {
        try {
            m_debug_utils = std::make_unique<DebugUtils>(m_instance, log);
        } catch (...) {
            vkDestroyInstance(m_instance, nullptr);
            throw;
        }
    }
}

Instance::~Instance() {
    m_debug_utils.reset();  // the messenger goes before its instance
    if (m_instance) vkDestroyInstance(m_instance, nullptr);
}

std::vector<VkPhysicalDevice> Instance::physical_devices() const {
    uint32_t count = 0;
    vk_check(vkEnumeratePhysicalDevices(m_instance, &count, nullptr), "vkEnumeratePhysicalDevices");
    std::vector<VkPhysicalDevice> devices(count);
    vk_check(vkEnumeratePhysicalDevices(m_instance, &count, devices.data()),
             "vkEnumeratePhysicalDevices");
    devices.resize(count);
    return devices;
}

}  // namespace mvpl::gpu
