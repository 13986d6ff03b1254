#pragma once
// A VkBuffer with its own memory. Device buffers are filled and read through staging copies;
// upload/readback buffers are persistently mapped. Vulkan-free to include.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "engine/gpu/memory.h"
#include "engine/gpu/vk_fwd.h"

namespace mvpl::gpu {

class Context;

// What the GPU does with a buffer. Transfer source and destination are always included.
enum class BufferUsage : uint32_t {
    none = 0,
    storage = 1u << 0,
    uniform = 1u << 1,
    vertex = 1u << 2,
    index = 1u << 3,
    indirect = 1u << 4,
};
constexpr BufferUsage operator|(BufferUsage a, BufferUsage b) {
    return BufferUsage(uint32_t(a) | uint32_t(b));
}
constexpr bool has(BufferUsage set, BufferUsage bit) {
    return (uint32_t(set) & uint32_t(bit)) != 0;
}

class Buffer {
public:
    Buffer() = default;
    // size > 0 bytes. name appears in errors and validation messages.
    Buffer(Context& context, uint64_t size, BufferUsage usage,
           MemoryLocation location = MemoryLocation::device, std::string_view name = {});
    ~Buffer();
    Buffer(Buffer&& other) noexcept;
    Buffer& operator=(Buffer&& other) noexcept;
    Buffer(const Buffer&) = delete;
    Buffer& operator=(const Buffer&) = delete;

    bool valid() const { return m_buffer != nullptr; }
    uint64_t size() const { return m_size; }
    BufferUsage usage() const { return m_usage; }
    MemoryLocation location() const { return m_location; }
    const std::string& name() const { return m_name; }
    VkBuffer handle() const { return m_buffer; }
    // Host pointer for upload/readback buffers; nullptr for device buffers.
    std::byte* mapped() const { return m_allocation.mapped; }

    // Copies bytes into [offset, offset + bytes.size()). For a device buffer this is a staging
    // copy and a submit_and_wait, so do not call it inside a recording.
    void upload(std::span<const std::byte> bytes, uint64_t offset = 0);
    // Copies [offset, offset + out.size()) out, after all submitted work (same caveat).
    void download(std::span<std::byte> out, uint64_t offset = 0) const;

    template <class T>
    void upload(const std::vector<T>& values, uint64_t offset = 0) {
        upload(std::as_bytes(std::span(values)), offset);
    }
    template <class T>
    std::vector<T> download(size_t count, uint64_t offset = 0) const {
        std::vector<T> values(count);
        download(std::as_writable_bytes(std::span(values)), offset);
        return values;
    }

private:
    void release() noexcept;
    void check_range(uint64_t offset, uint64_t bytes, const char* what) const;

    Context* m_context = nullptr;
    VkBuffer m_buffer = nullptr;
    Allocation m_allocation;
    uint64_t m_size = 0;
    BufferUsage m_usage = BufferUsage::none;
    MemoryLocation m_location = MemoryLocation::device;
    std::string m_name;
};

}  // namespace mvpl::gpu
