#include "engine/gpu/memory.h"

#include <vulkan/vulkan.h>

#include <bit>
#include <string>

#include "engine/gpu/gpu_error.h"
#include "engine/gpu/vk_check.h"

namespace mvpl::gpu {
namespace {

struct TypeWish {
    VkMemoryPropertyFlags required = 0;
    VkMemoryPropertyFlags preferred = 0;
    VkMemoryPropertyFlags avoided = 0;
};

TypeWish wish_for(MemoryLocation location) {
    // Coherent host memory is guaranteed to exist by the spec, and it spares us flush/invalidate
    // calls with nonCoherentAtomSize alignment.
    constexpr VkMemoryPropertyFlags kHost =
        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    switch (location) {
        case MemoryLocation::upload:
            // Device-local host-visible memory (ReBAR) would be faster to read on the GPU but is
            // often a small heap; staging and uniforms do not need it.
            return {kHost, 0, VK_MEMORY_PROPERTY_HOST_CACHED_BIT};
        case MemoryLocation::readback:
            // CPU reads from uncached memory are an order of magnitude slower.
            return {kHost, VK_MEMORY_PROPERTY_HOST_CACHED_BIT, 0};
        case MemoryLocation::device:
        default:
            // Keep device-only resources out of the small host-visible device heap if possible.
            return {0, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT};
    }
}

const char* location_name(MemoryLocation location) {
    switch (location) {
        case MemoryLocation::upload:
            return "upload";
        case MemoryLocation::readback:
            return "readback";
        default:
            return "device";
    }
}

}  // namespace

MemoryAllocator::MemoryAllocator(VkPhysicalDevice physical_device, VkDevice device)
    : m_device(device) {
    VkPhysicalDeviceMemoryProperties props{};
    vkGetPhysicalDeviceMemoryProperties(physical_device, &props);
    for (uint32_t i = 0; i < props.memoryTypeCount; ++i) {
        m_type_flags.push_back(props.memoryTypes[i].propertyFlags);
    }
}

int MemoryAllocator::find_memory_type(uint32_t memory_type_bits, MemoryLocation location) const {
    const TypeWish wish = wish_for(location);
    int best = -1;
    int best_score = -1;
    for (uint32_t i = 0; i < m_type_flags.size(); ++i) {
        const VkMemoryPropertyFlags flags = m_type_flags[i];
        if (!(memory_type_bits & (1u << i)) || (flags & wish.required) != wish.required) continue;
        // Preferred bits count more than avoided ones; ties keep the lower index, which the
        // spec orders from the implementation's best type downwards.
        const int score = 2 * std::popcount(flags & wish.preferred) +
                          (std::popcount(flags & wish.avoided) == 0 ? 1 : 0);
        if (score > best_score) {
            best = int(i);
            best_score = score;
        }
    }
    return best;
}

Allocation MemoryAllocator::allocate(uint64_t size, uint32_t memory_type_bits,
                                     MemoryLocation location, std::string_view what) {
    const int type = find_memory_type(memory_type_bits, location);
    if (type < 0) {
        throw GpuError(std::string(what) + ": no " + location_name(location) +
                       " memory type fits (memoryTypeBits " + std::to_string(memory_type_bits) +
                       ")");
    }
    VkMemoryAllocateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
    info.allocationSize = size;
    info.memoryTypeIndex = uint32_t(type);
    Allocation allocation;
    const VkResult result = vkAllocateMemory(m_device, &info, nullptr, &allocation.memory);
    if (result != VK_SUCCESS) {
        vk_check(result, std::string(what) + ": vkAllocateMemory(" + std::to_string(size) +
                             " bytes, " + location_name(location) + ")");
    }
    allocation.size = size;
    allocation.memory_type = uint32_t(type);
    if (location != MemoryLocation::device) {
        void* mapped = nullptr;
        const VkResult map_result =
            vkMapMemory(m_device, allocation.memory, 0, VK_WHOLE_SIZE, 0, &mapped);
        if (map_result != VK_SUCCESS) {
            vkFreeMemory(m_device, allocation.memory, nullptr);
            vk_check(map_result, std::string(what) + ": vkMapMemory");
        }
        allocation.mapped = static_cast<std::byte*>(mapped);
    }
    const uint64_t now = m_bytes += size;
    // Lock-free maximum: retry while another thread raised the peak below our value.
    uint64_t peak = m_peak.load();
    while (now > peak && !m_peak.compare_exchange_weak(peak, now)) {
    }
    ++m_count;
    return allocation;
}

void MemoryAllocator::free(Allocation& allocation) {
    if (!allocation.memory) return;
    // vkFreeMemory unmaps implicitly.
    vkFreeMemory(m_device, allocation.memory, nullptr);
    m_bytes -= allocation.size;
    --m_count;
    allocation = Allocation{};
}

}  // namespace mvpl::gpu
