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

}  // namespace mvpl::render
