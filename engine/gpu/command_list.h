#pragma once
// The command buffer being recorded inside Context::submit_and_wait, with the few commands the
// engine needs without Vulkan in the caller (copies, clears, compute dispatches). Passes that
// need more record into handle() directly. Vulkan-free to include.
#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <variant>

#include "engine/gpu/vk_fwd.h"

namespace mvpl::gpu {

class Buffer;
class ComputePipeline;
class Context;
class Image;

// One descriptor of a dispatch, in binding order.
using Resource = std::variant<const Buffer*, const Image*>;

class CommandList {
public:
    CommandList(Context& context, VkCommandBuffer cmd) : m_context(&context), m_cmd(cmd) {}

    Context& context() const { return *m_context; }
    VkCommandBuffer handle() const { return m_cmd; }

    // Every write recorded before is visible to every command recorded after. Coarse, and
    // cheap on lavapipe; passes on real GPUs may want narrower barriers.
    void barrier();

    void copy_buffer(const Buffer& src, Buffer& dst, uint64_t bytes, uint64_t src_offset = 0,
                     uint64_t dst_offset = 0);
    // Tightly packed layers from src (offset 0) into image layers [base_layer, +layer_count).
    void copy_buffer_to_image(const Buffer& src, Image& dst, uint32_t base_layer,
                              uint32_t layer_count);
    void copy_image_to_buffer(const Image& src, Buffer& dst, uint32_t base_layer,
                              uint32_t layer_count);
    // Layer ranges of src into layer ranges of dst (same size and format, distinct images).
    struct LayerCopy {
        uint32_t src_layer = 0;
        uint32_t dst_layer = 0;
        uint32_t count = 1;
    };
    void copy_image_layers(const Image& src, Image& dst, std::span<const LayerCopy> copies);
    // Fills layers [base_layer, +layer_count) of a colour image (layer_count 0: to the end).
    void clear_color(Image& image, const std::array<float, 4>& rgba, uint32_t base_layer = 0,
                     uint32_t layer_count = 0);
    void clear_depth(Image& image, float depth, uint32_t base_layer = 0, uint32_t layer_count = 0);

    // Binds pipeline, one transient descriptor set holding resources (in binding order, matching
    // the pipeline's ComputeLayout) and push_constants, then dispatches groups.
    void dispatch(const ComputePipeline& pipeline, std::span<const Resource> resources,
                  std::span<const std::byte> push_constants, uint32_t groups_x,
                  uint32_t groups_y = 1, uint32_t groups_z = 1);
    void dispatch(const ComputePipeline& pipeline, std::initializer_list<Resource> resources,
                  std::span<const std::byte> push_constants, uint32_t groups_x,
                  uint32_t groups_y = 1, uint32_t groups_z = 1) {
        dispatch(pipeline, std::span(resources.begin(), resources.size()), push_constants, groups_x,
                 groups_y, groups_z);
    }

    // Called once by Image's constructor: UNDEFINED → GENERAL, the layout images keep.
    void initialize_layout(const Image& image);

private:
    Context* m_context;
    VkCommandBuffer m_cmd;
};

// Push constants as bytes: cmd.dispatch(pipe, {&a, &b}, push_bytes(params), n).
template <class T>
std::span<const std::byte> push_bytes(const T& value) {
    return std::as_bytes(std::span(&value, 1));
}

}  // namespace mvpl::gpu
