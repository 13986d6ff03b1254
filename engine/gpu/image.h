#pragma once
// A 2D image, layered or a cube-map array, with its own memory and views. Vulkan-free to include.
//
// Images live in VK_IMAGE_LAYOUT_GENERAL from creation on: it is valid for every use mvpl has
// (transfer, storage, sampling, attachments), lavapipe ignores layouts anyway, and it spares
// every pass layout tracking. A pass that measures a gain from optimal layouts on a real GPU can
// transition and transition back.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "engine/gpu/format.h"
#include "engine/gpu/memory.h"
#include "engine/gpu/vk_fwd.h"

namespace mvpl::gpu {

class Buffer;
class Context;

// What the GPU does with an image. Transfer source and destination are always included.
enum class ImageUsage : uint32_t {
    none = 0,
    sampled = 1u << 0,
    storage = 1u << 1,
    color_attachment = 1u << 2,
    depth_attachment = 1u << 3,
};
constexpr ImageUsage operator|(ImageUsage a, ImageUsage b) {
    return ImageUsage(uint32_t(a) | uint32_t(b));
}
constexpr bool has(ImageUsage set, ImageUsage bit) {
    return (uint32_t(set) & uint32_t(bit)) != 0;
}

struct ImageDesc {
    uint32_t width = 1;
    uint32_t height = 1;
    // Array layers. A cube-map array has 6 per cube, faces in the order +X −X +Y −Y +Z −Z.
    uint32_t layers = 1;
    Format format = Format::rgba32_float;
    ImageUsage usage = ImageUsage::sampled;
    // Cube-compatible, viewed as a cube-map array (samplerCubeArray in GLSL, even for one cube:
    // one shader declaration for any batch size). Needs width == height and layers % 6 == 0.
    bool cube = false;
};

class Image {
public:
    Image() = default;
    // Submits the initial layout transition: not inside a submit_and_wait recording.
    Image(Context& context, const ImageDesc& desc, std::string_view name = {});
    ~Image();
    Image(Image&& other) noexcept;
    Image& operator=(Image&& other) noexcept;
    Image(const Image&) = delete;
    Image& operator=(const Image&) = delete;

    bool valid() const { return m_image != nullptr; }
    const ImageDesc& desc() const { return m_desc; }
    uint32_t width() const { return m_desc.width; }
    uint32_t height() const { return m_desc.height; }
    uint32_t layers() const { return m_desc.layers; }
    Format format() const { return m_desc.format; }
    const std::string& name() const { return m_name; }
    // Bytes of one tightly packed layer.
    uint64_t layer_bytes() const;

    VkImage handle() const { return m_image; }
    // The whole image: 2D (one layer), 2D array, or cube-map array (cube).
    VkImageView view() const { return m_view; }
    // One layer as a 2D view, to render one cube face at a time (multiview writes wrong layers
    // on lavapipe). Only for attachment usages; nullptr otherwise.
    VkImageView layer_view(uint32_t layer) const;

    // Uploads layer_count tightly packed layers starting at base_layer (staging copy and
    // submit_and_wait: not inside a recording).
    void upload(std::span<const std::byte> pixels, uint32_t base_layer = 0,
                uint32_t layer_count = 1);
    // The same through the caller's upload buffer of at least pixels.size() bytes: uploads in a
    // row reuse its pages, where a fresh buffer each faults every page in again (on a CPU device
    // such as lavapipe, that first touch is most of a large texture's upload).
    void upload(std::span<const std::byte> pixels, Buffer& staging, uint32_t base_layer = 0,
                uint32_t layer_count = 1);
    // Reads layer_count layers back, tightly packed (same caveat).
    std::vector<std::byte> download(uint32_t base_layer = 0, uint32_t layer_count = 1) const;

    template <class T>
    void upload(const std::vector<T>& pixels, uint32_t base_layer = 0, uint32_t layer_count = 1) {
        upload(std::as_bytes(std::span(pixels)), base_layer, layer_count);
    }
    template <class T>
    std::vector<T> download_as(uint32_t base_layer = 0, uint32_t layer_count = 1) const {
        const std::vector<std::byte> bytes = download(base_layer, layer_count);
        std::vector<T> values(bytes.size() / sizeof(T));
        std::memcpy(values.data(), bytes.data(), values.size() * sizeof(T));
        return values;
    }

private:
    void release() noexcept;
    void check_layers(uint32_t base_layer, uint32_t layer_count) const;

    Context* m_context = nullptr;
    ImageDesc m_desc;
    std::string m_name;
    VkImage m_image = nullptr;
    VkImageView m_view = nullptr;
    std::vector<VkImageView> m_layer_views;
    Allocation m_allocation;
};

}  // namespace mvpl::gpu
