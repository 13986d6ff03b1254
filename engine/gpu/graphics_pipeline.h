#pragma once
// A graphics pipeline for dynamic rendering (Vulkan 1.3, no render pass objects; begin/end
// rendering into layers of mvpl Images in rendering.h) and the few commands that draw with it:
// non-indexed draws from one vertex buffer and indexed draws of index ranges. Vulkan-free to
// include.
//
// The shape is what the render passes need and no more: one interleaved vertex buffer, push
// constants visible to both stages (per-draw data fits in 128 bytes, the guaranteed push-constant
// size), optionally one descriptor set of sampled images for the fragment stage (the textures
// that alpha-tested materials read; bind_images), no culling unless asked (shadow maps keep back
// faces but those of closed solids; the G-buffer discards those of one-sided materials per draw,
// in its fragment stage), dynamic
// viewport and scissor, no blending. Depth is reversed (compare GREATER, clear to 0, z_ndc = near /
// distance): floats then resolve depth with the same relative precision at every distance, which an
// infinite far plane and any scene scale need.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "engine/gpu/compute_pipeline.h"
#include "engine/gpu/format.h"
#include "engine/gpu/vk_fwd.h"

namespace mvpl::gpu {

class Buffer;
class CommandList;
class Context;
class Image;

enum class VertexFormat { float3, float4, uint1 };

struct VertexAttribute {
    VertexFormat format = VertexFormat::float3;
    uint32_t offset = 0;  // bytes into the vertex; location = index in GraphicsLayout::attributes
};

struct GraphicsLayout {
    uint32_t vertex_stride = 0;
    std::vector<VertexAttribute> attributes;
    std::vector<Format> color_formats;  // fragment output location i writes attachment i
    bool depth = false;                 // a d32_float depth attachment, test GREATER and write
    uint32_t push_constant_bytes = 0;   // one range, vertex and fragment stages
    // Discard back faces (shadow maps of closed solids, ShadowPass); front faces wind clockwise
    // in the framebuffer when front_clockwise, else counter-clockwise (Vulkan's "positive area").
    bool cull_back = false;
    bool front_clockwise = false;
    // Whether back faces are culled is set per draw instead (set_cull_back), cull_back ignored.
    bool dynamic_cull = false;
    // Set 0 of the fragment stage, binding i; sampled_image only (nearest, clamp to edge: the
    // generated texture code filters and wraps itself). Empty: no descriptor set.
    std::vector<BindingType> bindings;
};

class GraphicsPipeline {
public:
    // vertex_spirv/fragment_spirv: compile_glsl output. name appears in errors and validation.
    GraphicsPipeline(Context& context, std::span<const uint32_t> vertex_spirv,
                     std::span<const uint32_t> fragment_spirv, GraphicsLayout layout,
                     std::string_view name);
    ~GraphicsPipeline();
    GraphicsPipeline(const GraphicsPipeline&) = delete;
    GraphicsPipeline& operator=(const GraphicsPipeline&) = delete;

    const GraphicsLayout& layout() const { return m_layout; }
    const std::string& name() const { return m_name; }
    VkPipeline handle() const { return m_pipeline; }
    VkPipelineLayout pipeline_layout() const { return m_pipeline_layout; }
    VkDescriptorSetLayout set_layout() const { return m_set_layout; }

private:
    // Set 0's layout: the bindings, each with the immutable nearest sampler.
    void create_set_layout(VkDevice device, const std::string& what);
    // Set 0 (if any) and the push-constant range.
    void create_pipeline_layout(VkDevice device);
    void release() noexcept;

    Context* m_context;
    GraphicsLayout m_layout;
    std::string m_name;
    VkSampler m_sampler = nullptr;
    VkDescriptorSetLayout m_set_layout = nullptr;
    VkPipelineLayout m_pipeline_layout = nullptr;
    VkPipeline m_pipeline = nullptr;
};

// Binds images (one per layout binding, in order) as the pipeline's set 0 for the draws recorded
// after it, inside a submit_and_wait recording (a transient descriptor set).
void bind_images(CommandList& cmd, const GraphicsPipeline& pipeline,
                 std::span<const Image* const> images);
// The same in two steps, for a pass that switches pipelines between its draws: a transient set
// holding images for pipeline's layout (null without bindings), and binding it again (binding
// another pipeline's set replaces it).
VkDescriptorSet write_image_set(CommandList& cmd, const GraphicsPipeline& pipeline,
                                std::span<const Image* const> images);
void bind_image_set(CommandList& cmd, const GraphicsPipeline& pipeline, VkDescriptorSet set);

// Culls back faces (or not) in the draws that follow, of a pipeline with dynamic_cull (inside
// begin/end_rendering).
void set_cull_back(CommandList& cmd, const GraphicsPipeline& pipeline, bool cull);

// Binds pipeline and vertices, pushes push_constants (the layout's size) and draws
// vertex_count vertices from first_vertex as a triangle list.
void draw(CommandList& cmd, const GraphicsPipeline& pipeline, const Buffer& vertices,
          std::span<const std::byte> push_constants, uint32_t first_vertex, uint32_t vertex_count);

// A run of a uint32 index buffer, drawn as a triangle list.
struct IndexRange {
    uint32_t first_index = 0;
    uint32_t index_count = 0;
};

// Binds pipeline, vertices and indices once, pushes push_constants and draws every range.
void draw_indexed(CommandList& cmd, const GraphicsPipeline& pipeline, const Buffer& vertices,
                  const Buffer& indices, std::span<const std::byte> push_constants,
                  std::span<const IndexRange> ranges);

}  // namespace mvpl::gpu
