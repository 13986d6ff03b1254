#include "engine/gpu/compute_pipeline.h"

#include <vulkan/vulkan.h>

#include <algorithm>

#include "engine/gpu/context.h"
#include "engine/gpu/gpu_error.h"
#include "engine/gpu/vk_check.h"
#include "engine/gpu/vk_types.h"

namespace mvpl::gpu {

VkSampler create_nearest_sampler(VkDevice device) {
    VkSamplerCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO;
    info.magFilter = VK_FILTER_NEAREST;
    info.minFilter = VK_FILTER_NEAREST;
    info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    info.addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    info.addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    info.maxLod = 0.0f;
    VkSampler sampler = VK_NULL_HANDLE;
    vk_check(vkCreateSampler(device, &info, nullptr, &sampler), "vkCreateSampler");
    return sampler;
}

VkDescriptorType to_vk_descriptor_type(BindingType type) {
    switch (type) {
        case BindingType::uniform_buffer:
            return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
        case BindingType::storage_image:
            return VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
        case BindingType::sampled_image:
            return VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
        case BindingType::storage_buffer:
        default:
            return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    }
}

ComputePipeline::ComputePipeline(Context& context, std::span<const uint32_t> spirv,
                                 ComputeLayout layout, std::string_view name)
    : m_context(&context), m_layout(std::move(layout)), m_name(name) {
    const VkDevice device = context.device();
    const uint32_t max_push = context.device_info().limits.max_push_constants_size;
    if (m_layout.push_constant_bytes % 4 != 0 || m_layout.push_constant_bytes > max_push) {
        throw GpuError(
            "compute pipeline '" + m_name + "': " + std::to_string(m_layout.push_constant_bytes) +
            " push-constant bytes (a multiple of 4, at most " + std::to_string(max_push) + ")");
    }
    if (spirv.empty()) throw GpuError("compute pipeline '" + m_name + "': no SPIR-V");

    VkShaderModule module = VK_NULL_HANDLE;
    try {
        const bool samples = std::find(m_layout.bindings.begin(), m_layout.bindings.end(),
                                       BindingType::sampled_image) != m_layout.bindings.end();
        if (samples) {
            // Immutable: baked into the set layout, so dispatches bind only the image.
            m_sampler = create_nearest_sampler(device);
        }
        std::vector<VkDescriptorSetLayoutBinding> bindings;
        for (uint32_t i = 0; i < m_layout.bindings.size(); ++i) {
            VkDescriptorSetLayoutBinding b{};
            b.binding = i;
            b.descriptorType = to_vk_descriptor_type(m_layout.bindings[i]);
            b.descriptorCount = 1;
            b.stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
            if (m_layout.bindings[i] == BindingType::sampled_image)
                b.pImmutableSamplers = &m_sampler;
            bindings.push_back(b);
        }
        VkDescriptorSetLayoutCreateInfo set_info{};
        set_info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
        set_info.bindingCount = uint32_t(bindings.size());
        set_info.pBindings = bindings.data();
        vk_check(vkCreateDescriptorSetLayout(device, &set_info, nullptr, &m_set_layout),
                 "vkCreateDescriptorSetLayout(" + m_name + ")");

        VkPushConstantRange push{};
        push.stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
        push.size = m_layout.push_constant_bytes;
        VkPipelineLayoutCreateInfo layout_info{};
        layout_info.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
        layout_info.setLayoutCount = 1;
        layout_info.pSetLayouts = &m_set_layout;
        layout_info.pushConstantRangeCount = push.size > 0 ? 1 : 0;
        layout_info.pPushConstantRanges = &push;
        vk_check(vkCreatePipelineLayout(device, &layout_info, nullptr, &m_pipeline_layout),
                 "vkCreatePipelineLayout(" + m_name + ")");

        VkShaderModuleCreateInfo module_info{};
        module_info.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
        module_info.codeSize = spirv.size_bytes();
        module_info.pCode = spirv.data();
        vk_check(vkCreateShaderModule(device, &module_info, nullptr, &module),
                 "vkCreateShaderModule(" + m_name + ")");
        VkComputePipelineCreateInfo info{};
        info.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO;
        info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
        info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
        info.stage.module = module;
        info.stage.pName = "main";
        info.layout = m_pipeline_layout;
        vk_check(vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &m_pipeline),
                 "vkCreateComputePipelines(" + m_name + ")");
        // The pipeline keeps what it needs; the module is only an input.
        vkDestroyShaderModule(device, module, nullptr);
        module = VK_NULL_HANDLE;
    } catch (...) {
        if (module) vkDestroyShaderModule(device, module, nullptr);
        release();
        throw;
    }
    context.set_debug_name(VK_OBJECT_TYPE_PIPELINE, uint64_t(m_pipeline), m_name);
}

ComputePipeline::~ComputePipeline() {
    release();
}

void ComputePipeline::release() noexcept {
    const VkDevice device = m_context->device();
    if (m_pipeline) vkDestroyPipeline(device, m_pipeline, nullptr);
    if (m_pipeline_layout) vkDestroyPipelineLayout(device, m_pipeline_layout, nullptr);
    if (m_set_layout) vkDestroyDescriptorSetLayout(device, m_set_layout, nullptr);
    if (m_sampler) vkDestroySampler(device, m_sampler, nullptr);
    m_pipeline = nullptr;
    m_pipeline_layout = nullptr;
    m_set_layout = nullptr;
    m_sampler = nullptr;
}

}  // namespace mvpl::gpu
