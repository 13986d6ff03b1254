#pragma once
// What the GPU renderer's images take for a set of options, checked before anything is
// allocated, so that a resolution, shadow resolution or batch that cannot fit is refused up front
// with the estimate (exit 2) instead of failing inside Vulkan's allocator half-way. Vulkan-free.
#include <cstdint>
#include <string>

#include "engine/gpu/device_info.h"
#include "engine/render/vpl_renderer.h"

namespace mvpl::render {

struct MemoryEstimate {
    uint64_t device_bytes = 0;   // every image the passes create
    uint64_t largest_image = 0;  // the biggest single allocation among them
    uint64_t host_bytes = 0;     // the read-back and the linear image on the host
};

MemoryEstimate estimate_memory(const RenderOptions& options);

// Empty when the options fit `device` and `host_bytes` of host memory (host_memory_bytes()); else
// one sentence:
// what needs how much and what the device or host has. `devices`: logical devices on `device`
// (VplRenderer's), each with every image.
std::string memory_shortfall(const RenderOptions& options, const gpu::DeviceInfo& device,
                             uint64_t host_bytes, uint32_t devices = 1);

// The memory kept shadow maps may take (RenderOptions::kept_shadow_bytes): what was asked, at
// most 1/kKeptMapsShare of the device's largest local heap (of the host's physical memory on a
// CPU device: host_memory_bytes()). A cache, not a requirement: memory_shortfall() does not count
// it, and a small machine keeps fewer maps instead of refusing the render.
constexpr uint64_t kKeptMapsShare = 4;
uint64_t kept_maps_budget(uint64_t requested, const gpu::DeviceInfo& device, uint64_t host_bytes);

}  // namespace mvpl::render
