#pragma once
// Device memory: picks a memory type for what a resource is used for and allocates it.
//
// One VkDeviceMemory per buffer or image. mvpl holds tens of resources (G-buffer, a cube-map
// array, VPL buffers), far below maxMemoryAllocationCount (≥ 4096), so sub-allocation would only
// add fragmentation bookkeeping. Revisit if per-VPL or per-mesh resources appear.
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "engine/gpu/vk_fwd.h"

namespace mvpl::gpu {

enum class MemoryLocation {
    device,    // GPU-only; filled and read through staging copies
    upload,    // host-visible + coherent, written by the CPU (staging, per-frame uniforms)
    readback,  // host-visible + coherent, preferably cached, read by the CPU
};

struct Allocation {
    VkDeviceMemory memory = nullptr;
    uint64_t size = 0;
    uint32_t memory_type = 0;
    std::byte* mapped = nullptr;  // persistently mapped for upload/readback; nullptr for device
};

class MemoryAllocator {
public:
    MemoryAllocator(VkPhysicalDevice physical_device, VkDevice device);
    ~MemoryAllocator() = default;
    MemoryAllocator(const MemoryAllocator&) = delete;
    MemoryAllocator& operator=(const MemoryAllocator&) = delete;

    // memory_type_bits: VkMemoryRequirements::memoryTypeBits of the resource. what names the
    // resource in the error when no memory type fits or the heap is full.
    Allocation allocate(uint64_t size, uint32_t memory_type_bits, MemoryLocation location,
                        std::string_view what);
    void free(Allocation& allocation);

    // Memory type index for the location among memory_type_bits, or -1.
    int find_memory_type(uint32_t memory_type_bits, MemoryLocation location) const;

    uint64_t allocated_bytes() const { return m_bytes.load(); }
    uint32_t allocation_count() const { return m_count.load(); }
    // High-water mark of allocated_bytes() since construction or the last reset_peak() (mvpl
    // bench reports it as the peak device memory; Vulkan has no portable per-process query).
    uint64_t peak_bytes() const { return m_peak.load(); }
    void reset_peak() { m_peak.store(m_bytes.load()); }

private:
    VkDevice m_device = nullptr;
    std::vector<uint32_t> m_type_flags;  // VkMemoryPropertyFlags per memory type
    std::atomic<uint64_t> m_bytes{0};
    std::atomic<uint32_t> m_count{0};
    std::atomic<uint64_t> m_peak{0};
};

}  // namespace mvpl::gpu
