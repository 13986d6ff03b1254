#include "engine/gpu/device_info.h"

#include <vulkan/vulkan.h>

#include "engine/gpu/instance.h"
#include "engine/gpu/vk_check.h"

namespace mvpl::gpu {
namespace {

constexpr uint32_t kVendorNvidia = 0x10DE;

std::string format_driver_version(uint32_t vendor_id, uint32_t v) {
    // Vendors encode driverVersion as they like; these are the known layouts.
    if (vendor_id == kVendorNvidia) {
        return std::to_string((v >> 22) & 0x3ff) + "." + std::to_string((v >> 14) & 0xff) + "." +
               std::to_string((v >> 6) & 0xff) + "." + std::to_string(v & 0x3f);
    }
#ifdef _WIN32
    constexpr uint32_t kVendorIntel = 0x8086;
    if (vendor_id == kVendorIntel)
        return std::to_string(v >> 14) + "." + std::to_string(v & 0x3fff);
#endif
    // VK_MAKE_VERSION layout (Mesa, AMD, Intel on Linux), without the API variant mask.
    return std::to_string(v >> 22) + "." + std::to_string((v >> 12) & 0x3ff) + "." +
           std::to_string(v & 0xfff);
}

DeviceType to_device_type(VkPhysicalDeviceType type) {
    switch (type) {
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
            return DeviceType::integrated_gpu;
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
            return DeviceType::discrete_gpu;
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
            return DeviceType::virtual_gpu;
        case VK_PHYSICAL_DEVICE_TYPE_CPU:
            return DeviceType::cpu;
        default:
            return DeviceType::other;
    }
}

// The limits mvpl reads, from the device's properties `p`.
DeviceLimits device_limits(VkPhysicalDevice device, const VkPhysicalDeviceProperties& p) {
    const VkPhysicalDeviceLimits& l = p.limits;
    DeviceLimits m;
    m.max_image_dimension_2d = l.maxImageDimension2D;
    m.max_image_dimension_cube = l.maxImageDimensionCube;
    m.max_image_array_layers = l.maxImageArrayLayers;
    m.max_framebuffer_width = l.maxFramebufferWidth;
    m.max_framebuffer_height = l.maxFramebufferHeight;
    m.max_framebuffer_layers = l.maxFramebufferLayers;
    m.max_compute_work_group_invocations = l.maxComputeWorkGroupInvocations;
    for (int i = 0; i < 3; ++i) {
        m.max_compute_work_group_size[i] = l.maxComputeWorkGroupSize[i];
        m.max_compute_work_group_count[i] = l.maxComputeWorkGroupCount[i];
    }
    m.max_push_constants_size = l.maxPushConstantsSize;
    m.max_storage_buffer_range = l.maxStorageBufferRange;
    m.max_bound_descriptor_sets = l.maxBoundDescriptorSets;
    m.max_memory_allocation_count = l.maxMemoryAllocationCount;
    m.timestamp_period = l.timestampPeriod;
    m.timestamp_compute_and_graphics = l.timestampComputeAndGraphics == VK_TRUE;
    if (p.apiVersion >= VK_API_VERSION_1_1) {
        VkPhysicalDeviceMaintenance3Properties maintenance3{};
        maintenance3.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_3_PROPERTIES;
        VkPhysicalDeviceProperties2 with_m3{};
        with_m3.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2;
        with_m3.pNext = &maintenance3;
        vkGetPhysicalDeviceProperties2(device, &with_m3);
        m.max_memory_allocation_size = maintenance3.maxMemoryAllocationSize;
    }
    return m;
}

// info.queue_family and its timestamp bits: a graphics+compute family (-1: none).
void pick_queue_family(VkPhysicalDevice device, DeviceInfo& info) {
    uint32_t family_count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device, &family_count, nullptr);
    std::vector<VkQueueFamilyProperties> families(family_count);
    vkGetPhysicalDeviceQueueFamilyProperties(device, &family_count, families.data());
    constexpr VkQueueFlags kWanted = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
    for (uint32_t i = 0; i < family_count; ++i) {
        if ((families[i].queueFlags & kWanted) != kWanted) continue;
        // Among graphics+compute families, one with timestamps wins (GpuTimer needs them).
        if (info.queue_family < 0 ||
            (info.timestamp_valid_bits == 0 && families[i].timestampValidBits > 0)) {
            info.queue_family = int(i);
            info.timestamp_valid_bits = families[i].timestampValidBits;
        }
    }
}

}  // namespace

bool DeviceInfo::usable() const {
    return unusable_reason().empty();
}

std::string DeviceInfo::unusable_reason() const {
    if (api_version < VK_API_VERSION_1_3) {
        return "Vulkan " + format_api_version(api_version) + " (mvpl needs 1.3)";
    }
    if (queue_family < 0) return "no queue family with both graphics and compute";
    if (!storage_image_extended_formats)
        return "no rg32f storage images (shaderStorageImageExtendedFormats)";
    return "";
}

DeviceInfo describe_device(VkPhysicalDevice device, int index) {
    VkPhysicalDeviceProperties2 props2{};
    props2.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2;
    VkPhysicalDeviceDriverProperties driver{};
    driver.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES;
    vkGetPhysicalDeviceProperties(device, &props2.properties);
    // Driver properties are core from 1.2; older devices only get the basic block.
    if (props2.properties.apiVersion >= VK_API_VERSION_1_2) {
        props2.pNext = &driver;
        vkGetPhysicalDeviceProperties2(device, &props2);
    }
    const VkPhysicalDeviceProperties& p = props2.properties;

    DeviceInfo info;
    info.index = index;
    info.name = p.deviceName;
    info.type = to_device_type(p.deviceType);
    info.vendor_id = p.vendorID;
    info.device_id = p.deviceID;
    info.api_version = p.apiVersion;
    info.driver_version = p.driverVersion;
    info.driver_version_string = format_driver_version(p.vendorID, p.driverVersion);
    info.driver_name = driver.driverName;
    info.driver_info = driver.driverInfo;

    info.limits = device_limits(device, p);

    VkPhysicalDeviceMemoryProperties memory{};
    vkGetPhysicalDeviceMemoryProperties(device, &memory);
    for (uint32_t i = 0; i < memory.memoryHeapCount; ++i) {
        info.heaps.push_back({memory.memoryHeaps[i].size, (memory.memoryHeaps[i].flags &
                                                           VK_MEMORY_HEAP_DEVICE_LOCAL_BIT) != 0});
    }

    pick_queue_family(device, info);

    VkPhysicalDeviceFeatures features{};
    vkGetPhysicalDeviceFeatures(device, &features);
    info.image_cube_array = features.imageCubeArray == VK_TRUE;
    info.storage_image_extended_formats = features.shaderStorageImageExtendedFormats == VK_TRUE;
    return info;
}

std::vector<DeviceInfo> enumerate_devices() {
    const Instance instance("", nullptr);
    std::vector<DeviceInfo> devices;
    const std::vector<VkPhysicalDevice> physical = instance.physical_devices();
    for (size_t i = 0; i < physical.size(); ++i)
        devices.push_back(describe_device(physical[i], int(i)));
    return devices;
}

uint32_t loader_api_version() {
    uint32_t version = VK_API_VERSION_1_0;  // a 1.0 loader lacks the query
    vk_check(vkEnumerateInstanceVersion(&version), "vkEnumerateInstanceVersion");
    return version;
}

int default_device_index(const std::vector<DeviceInfo>& devices) {
    for (DeviceType wanted : {DeviceType::discrete_gpu, DeviceType::integrated_gpu}) {
        for (const DeviceInfo& d : devices) {
            if (d.type == wanted && d.usable()) return d.index;
        }
    }
    for (const DeviceInfo& d : devices) {
        if (d.usable()) return d.index;
    }
    return -1;
}

const char* device_type_name(DeviceType type) {
    switch (type) {
        case DeviceType::integrated_gpu:
            return "integrated GPU";
        case DeviceType::discrete_gpu:
            return "discrete GPU";
        case DeviceType::virtual_gpu:
            return "virtual GPU";
        case DeviceType::cpu:
            return "CPU";
        default:
            return "other";
    }
}

std::string format_api_version(uint32_t version) {
    return std::to_string(VK_API_VERSION_MAJOR(version)) + "." +
           std::to_string(VK_API_VERSION_MINOR(version)) + "." +
           std::to_string(VK_API_VERSION_PATCH(version));
}

}  // namespace mvpl::gpu
