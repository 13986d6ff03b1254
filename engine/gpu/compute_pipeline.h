#pragma once
// A compute pipeline with one descriptor set of plain bindings and optional push constants: the
// shape of every compute pass mvpl plans (accumulation, resolve, tests). Vulkan-free to include.
//
// No descriptor indexing (lavapipe has none): a binding is one buffer or one image; many
// shadow cubes are one cube-map *array* image.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "engine/gpu/vk_fwd.h"

namespace mvpl::gpu {

class Context;

enum class BindingType {
    storage_buffer,  // GLSL `buffer`
    uniform_buffer,  // GLSL `uniform` block
    storage_image,   // GLSL `image2D` etc.
    sampled_image,   // GLSL `sampler2D`/`samplerCubeArray`; nearest filtering, clamp to edge
};

struct ComputeLayout {
    std::vector<BindingType> bindings;  // binding i of set 0
    uint32_t push_constant_bytes = 0;
};

class ComputePipeline {
public:
    // spirv: a compute shader (compile_glsl). name appears in errors and validation messages.
    ComputePipeline(Context& context, std::span<const uint32_t> spirv, ComputeLayout layout,
                    std::string_view name);
    ~ComputePipeline();
    ComputePipeline(const ComputePipeline&) = delete;
    ComputePipeline& operator=(const ComputePipeline&) = delete;

    const ComputeLayout& layout() const { return m_layout; }
    const std::string& name() const { return m_name; }
    VkPipeline handle() const { return m_pipeline; }
    VkPipelineLayout pipeline_layout() const { return m_pipeline_layout; }
    VkDescriptorSetLayout set_layout() const { return m_set_layout; }
    VkSampler sampler() const { return m_sampler; }

private:
    void release() noexcept;

    Context* m_context;
    ComputeLayout m_layout;
    std::string m_name;
    VkSampler m_sampler = nullptr;
    VkDescriptorSetLayout m_set_layout = nullptr;
    VkPipelineLayout m_pipeline_layout = nullptr;
    VkPipeline m_pipeline = nullptr;
};

}  // namespace mvpl::gpu
