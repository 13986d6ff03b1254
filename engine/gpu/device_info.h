#pragma once
// What a Vulkan device is and what it can do: for `mvpl info`, for choosing a device, and for
// sizing work (cube-map array layers, work groups). Vulkan-free.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "engine/gpu/vk_fwd.h"

namespace mvpl::gpu {

enum class DeviceType { other, integrated_gpu, discrete_gpu, virtual_gpu, cpu };

struct DeviceLimits {
    uint32_t max_image_dimension_2d = 0;
    uint32_t max_image_dimension_cube = 0;
    uint32_t max_image_array_layers = 0;
    uint32_t max_framebuffer_width = 0;
    uint32_t max_framebuffer_height = 0;
    uint32_t max_framebuffer_layers = 0;
    uint32_t max_compute_work_group_invocations = 0;
    std::array<uint32_t, 3> max_compute_work_group_size{};
    std::array<uint32_t, 3> max_compute_work_group_count{};
    uint32_t max_push_constants_size = 0;
    uint32_t max_storage_buffer_range = 0;
    uint32_t max_bound_descriptor_sets = 0;
    uint64_t max_memory_allocation_size = 0;
    uint32_t max_memory_allocation_count = 0;
    // Nanoseconds per timestamp tick.
    float timestamp_period = 0.0f;
    bool timestamp_compute_and_graphics = false;
};

struct MemoryHeapInfo {
    uint64_t size = 0;
    bool device_local = false;
};

struct DeviceInfo {
    int index = -1;  // position in enumerate_devices(), the number `--device N` takes
    std::string name;
    DeviceType type = DeviceType::other;
    uint32_t vendor_id = 0;
    uint32_t device_id = 0;
    uint32_t api_version = 0;     // VK_MAKE_API_VERSION encoding
    uint32_t driver_version = 0;  // vendor-specific encoding; see driver_version_string
    std::string driver_version_string;
    std::string driver_name;  // VkPhysicalDeviceDriverProperties, e.g. "llvmpipe"
    std::string driver_info;  // e.g. "Mesa 22.3.6 (LLVM 15.0.6)"
    DeviceLimits limits;
    std::vector<MemoryHeapInfo> heaps;
    // Queue family with graphics and compute (the one queue mvpl uses); -1 if there is none.
    int queue_family = -1;
    uint32_t timestamp_valid_bits = 0;  // of that queue family; 0: no timestamps
    bool image_cube_array = false;      // cube-map array views (the shadow pass needs them)
    bool storage_image_extended_formats = false;  // rg32f storage images (the shadow maps)

    // mvpl runs on it: Vulkan 1.3, a graphics+compute queue and rg32f storage images.
    bool usable() const;
    // Why it is not usable ("" if it is).
    std::string unusable_reason() const;
};

// Lists the devices the Vulkan loader sees, in its order. Throws GpuError without a loader/driver.
std::vector<DeviceInfo> enumerate_devices();

// The Vulkan version the loader implements (vkEnumerateInstanceVersion).
uint32_t loader_api_version();

// The device mvpl takes without --device: the first usable discrete GPU, else the first usable
// integrated GPU, else the first usable device (lavapipe in CI); -1 if none is usable.
int default_device_index(const std::vector<DeviceInfo>& devices);

// Describes one physical device; index is its position in the loader's list.
DeviceInfo describe_device(VkPhysicalDevice device, int index);

const char* device_type_name(DeviceType type);
// "1.3.230"
std::string format_api_version(uint32_t version);

}  // namespace mvpl::gpu
