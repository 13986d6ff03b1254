#include "engine/gpu/buffer.h"

#include <vulkan/vulkan.h>

#include <cstring>
#include <utility>

#include "engine/gpu/command_list.h"
#include "engine/gpu/context.h"
#include "engine/gpu/gpu_error.h"
#include "engine/gpu/vk_check.h"

namespace mvpl::gpu {
namespace {

VkBufferUsageFlags to_vk_usage(BufferUsage usage) {
    VkBufferUsageFlags flags = VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    if (has(usage, BufferUsage::storage)) flags |= VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    if (has(usage, BufferUsage::uniform)) flags |= VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT;
    if (has(usage, BufferUsage::vertex)) flags |= VK_BUFFER_USAGE_VERTEX_BUFFER_BIT;
    if (has(usage, BufferUsage::index)) flags |= VK_BUFFER_USAGE_INDEX_BUFFER_BIT;
    if (has(usage, BufferUsage::indirect)) flags |= VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT;
    return flags;
}

}  // namespace

Buffer::Buffer(Context& context, uint64_t size, BufferUsage usage, MemoryLocation location,
               std::string_view name)
    : m_context(&context),
      m_size(size),
      m_usage(usage),
      m_location(location),
      m_name(name.empty() ? "buffer" : name) {
    if (size == 0) throw GpuError("buffer '" + m_name + "': size 0");
    VkBufferCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
    info.size = size;
    info.usage = to_vk_usage(usage);
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    const VkDevice device = context.device();
    vk_check(vkCreateBuffer(device, &info, nullptr, &m_buffer), "vkCreateBuffer(" + m_name + ")");
    try {
        VkMemoryRequirements requirements{};
        vkGetBufferMemoryRequirements(device, m_buffer, &requirements);
        m_allocation = context.allocator().allocate(requirements.size, requirements.memoryTypeBits,
                                                    location, m_name);
        vk_check(vkBindBufferMemory(device, m_buffer, m_allocation.memory, 0),
                 "vkBindBufferMemory(" + m_name + ")");
    } catch (...) {
        release();
        throw;
    }
    context.set_debug_name(VK_OBJECT_TYPE_BUFFER, uint64_t(m_buffer), m_name);
}

Buffer::~Buffer() {
    release();
}

Buffer::Buffer(Buffer&& other) noexcept {
    *this = std::move(other);
}

Buffer& Buffer::operator=(Buffer&& other) noexcept {
    if (this != &other) {
        release();
        m_context = std::exchange(other.m_context, nullptr);
        m_buffer = std::exchange(other.m_buffer, nullptr);
        m_allocation = std::exchange(other.m_allocation, Allocation{});
        m_size = std::exchange(other.m_size, 0);
        m_usage = other.m_usage;
        m_location = other.m_location;
        m_name = std::move(other.m_name);
    }
    return *this;
}

void Buffer::release() noexcept {
    if (!m_context) return;
    if (m_buffer) vkDestroyBuffer(m_context->device(), m_buffer, nullptr);
    m_context->allocator().free(m_allocation);
    m_buffer = nullptr;
    m_context = nullptr;
}

void Buffer::check_range(uint64_t offset, uint64_t bytes, const char* what) const {
    if (!valid()) throw GpuError(std::string(what) + " on an empty Buffer");
    if (offset > m_size || bytes > m_size - offset) {
        throw GpuError("buffer '" + m_name + "': " + what + " of " + std::to_string(bytes) +
                       " bytes at offset " + std::to_string(offset) + " exceeds its " +
                       std::to_string(m_size) + " bytes");
    }
}

void Buffer::upload(std::span<const std::byte> bytes, uint64_t offset) {
    check_range(offset, bytes.size(), "upload");
    if (bytes.empty()) return;
    if (m_allocation.mapped) {
        // Coherent memory: visible to the next submission without a flush.
        std::memcpy(m_allocation.mapped + offset, bytes.data(), bytes.size());
        return;
    }
    Buffer staging(*m_context, bytes.size(), BufferUsage::none, MemoryLocation::upload,
                   m_name + " (staging)");
    std::memcpy(staging.mapped(), bytes.data(), bytes.size());
    m_context->submit_and_wait(
        [&](CommandList& cmd) { cmd.copy_buffer(staging, *this, bytes.size(), 0, offset); });
}

void Buffer::download(std::span<std::byte> out, uint64_t offset) const {
    check_range(offset, out.size(), "download");
    if (out.empty()) return;
    if (m_allocation.mapped) {
        // submit_and_wait ends each submission with a barrier to host reads; nothing is pending.
        std::memcpy(out.data(), m_allocation.mapped + offset, out.size());
        return;
    }
    Buffer staging(*m_context, out.size(), BufferUsage::none, MemoryLocation::readback,
                   m_name + " (readback)");
    m_context->submit_and_wait(
        [&](CommandList& cmd) { cmd.copy_buffer(*this, staging, out.size(), offset, 0); });
    std::memcpy(out.data(), staging.mapped(), out.size());
}

}  // namespace mvpl::gpu
