#include "engine/gpu/graphics_pipeline.h"

#include <vulkan/vulkan.h>

#include "engine/gpu/buffer.h"
#include "engine/gpu/command_list.h"
#include "engine/gpu/context.h"
#include "engine/gpu/gpu_error.h"
#include "engine/gpu/image.h"
#include "engine/gpu/vk_check.h"
#include "engine/gpu/vk_types.h"

namespace mvpl::gpu {
namespace {

VkFormat to_vk_vertex_format(VertexFormat format) {
    switch (format) {
        case VertexFormat::float4:
            return VK_FORMAT_R32G32B32A32_SFLOAT;
        case VertexFormat::uint1:
            return VK_FORMAT_R32_UINT;
        case VertexFormat::float3:
        default:
            return VK_FORMAT_R32G32B32_SFLOAT;
    }
}

VkShaderModule create_module(VkDevice device, std::span<const uint32_t> spirv,
                             const std::string& what) {
    if (spirv.empty()) throw GpuError(what + ": no SPIR-V");
    VkShaderModuleCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
    info.codeSize = spirv.size_bytes();
    info.pCode = spirv.data();
    VkShaderModule module = VK_NULL_HANDLE;
    vk_check(vkCreateShaderModule(device, &info, nullptr, &module),
             "vkCreateShaderModule(" + what + ")");
    return module;
}

constexpr VkShaderStageFlags kPushStages =
    VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;

VkPipelineShaderStageCreateInfo shader_stage(VkShaderStageFlagBits stage, VkShaderModule module) {
    VkPipelineShaderStageCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    info.stage = stage;
    info.module = module;
    info.pName = "main";
    return info;
}

VkPipelineInputAssemblyStateCreateInfo triangle_list_assembly() {
    VkPipelineInputAssemblyStateCreateInfo assembly{};
    assembly.sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO;
    assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    return assembly;
}

// One viewport and scissor, both dynamic state.
VkPipelineViewportStateCreateInfo one_viewport() {
    VkPipelineViewportStateCreateInfo viewport{};
    viewport.sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO;
    viewport.viewportCount = 1;
    viewport.scissorCount = 1;
    return viewport;
}

VkPipelineRasterizationStateCreateInfo rasterization(const GraphicsLayout& layout) {
    VkPipelineRasterizationStateCreateInfo raster{};
    raster.sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO;
    raster.polygonMode = VK_POLYGON_MODE_FILL;
    raster.cullMode = layout.cull_back ? VK_CULL_MODE_BACK_BIT : VK_CULL_MODE_NONE;
    raster.frontFace =
        layout.front_clockwise ? VK_FRONT_FACE_CLOCKWISE : VK_FRONT_FACE_COUNTER_CLOCKWISE;
    raster.lineWidth = 1.0f;
    return raster;
}

VkPipelineMultisampleStateCreateInfo single_sample() {
    VkPipelineMultisampleStateCreateInfo multisample{};
    multisample.sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO;
    multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    return multisample;
}

// Reversed depth (graphics_pipeline.h): nearer is greater.
VkPipelineDepthStencilStateCreateInfo reversed_depth(const GraphicsLayout& layout) {
    VkPipelineDepthStencilStateCreateInfo depth{};
    depth.sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO;
    depth.depthTestEnable = layout.depth ? VK_TRUE : VK_FALSE;
    depth.depthWriteEnable = layout.depth ? VK_TRUE : VK_FALSE;
    depth.depthCompareOp = VK_COMPARE_OP_GREATER;
    return depth;
}

// The pipeline object of `layout` from its two shader modules (vertex, fragment).
VkPipeline create_pipeline(VkDevice device, const GraphicsLayout& layout,
                           VkPipelineLayout pipeline_layout, const VkShaderModule (&modules)[2],
                           const std::string& name) {
    const VkPipelineShaderStageCreateInfo stages[2] = {
        shader_stage(VK_SHADER_STAGE_VERTEX_BIT, modules[0]),
        shader_stage(VK_SHADER_STAGE_FRAGMENT_BIT, modules[1])};

    VkVertexInputBindingDescription binding{0, layout.vertex_stride, VK_VERTEX_INPUT_RATE_VERTEX};
    std::vector<VkVertexInputAttributeDescription> attributes;
    for (uint32_t i = 0; i < layout.attributes.size(); ++i) {
        attributes.push_back(
            {i, 0, to_vk_vertex_format(layout.attributes[i].format), layout.attributes[i].offset});
    }
    VkPipelineVertexInputStateCreateInfo vertex_input{};
    vertex_input.sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO;
    vertex_input.vertexBindingDescriptionCount = attributes.empty() ? 0 : 1;
    vertex_input.pVertexBindingDescriptions = &binding;
    vertex_input.vertexAttributeDescriptionCount = uint32_t(attributes.size());
    vertex_input.pVertexAttributeDescriptions = attributes.data();

    const VkPipelineInputAssemblyStateCreateInfo assembly = triangle_list_assembly();
    const VkPipelineViewportStateCreateInfo viewport = one_viewport();
    const VkPipelineRasterizationStateCreateInfo raster = rasterization(layout);
    const VkPipelineMultisampleStateCreateInfo multisample = single_sample();
    const VkPipelineDepthStencilStateCreateInfo depth = reversed_depth(layout);

    std::vector<VkPipelineColorBlendAttachmentState> blend(layout.color_formats.size());
    std::vector<VkFormat> color_formats;
    for (size_t i = 0; i < blend.size(); ++i) {
        blend[i].colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                                  VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
        color_formats.push_back(to_vk_format(layout.color_formats[i]));
    }
    VkPipelineColorBlendStateCreateInfo blend_state{};
    blend_state.sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO;
    blend_state.attachmentCount = uint32_t(blend.size());
    blend_state.pAttachments = blend.data();

    // The cull mode is core dynamic state in Vulkan 1.3 (VK_EXT_extended_dynamic_state).
    const VkDynamicState dynamic_states[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR,
                                             VK_DYNAMIC_STATE_CULL_MODE};
    VkPipelineDynamicStateCreateInfo dynamic{};
    dynamic.sType = VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO;
    dynamic.dynamicStateCount = layout.dynamic_cull ? 3 : 2;
    dynamic.pDynamicStates = dynamic_states;

    VkPipelineRenderingCreateInfo rendering{};
    rendering.sType = VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO;
    rendering.colorAttachmentCount = uint32_t(color_formats.size());
    rendering.pColorAttachmentFormats = color_formats.data();
    rendering.depthAttachmentFormat = layout.depth ? VK_FORMAT_D32_SFLOAT : VK_FORMAT_UNDEFINED;

    VkGraphicsPipelineCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO;
    info.pNext = &rendering;
    info.stageCount = 2;
    info.pStages = stages;
    info.pVertexInputState = &vertex_input;
    info.pInputAssemblyState = &assembly;
    info.pViewportState = &viewport;
    info.pRasterizationState = &raster;
    info.pMultisampleState = &multisample;
    info.pDepthStencilState = &depth;
    info.pColorBlendState = &blend_state;
    info.pDynamicState = &dynamic;
    info.layout = pipeline_layout;
    VkPipeline pipeline = VK_NULL_HANDLE;
    vk_check(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline),
             "vkCreateGraphicsPipelines(" + name + ")");
    return pipeline;
}

}  // namespace

GraphicsPipeline::GraphicsPipeline(Context& context, std::span<const uint32_t> vertex_spirv,
                                   std::span<const uint32_t> fragment_spirv, GraphicsLayout layout,
                                   std::string_view name)
    : m_context(&context), m_layout(std::move(layout)), m_name(name) {
    const VkDevice device = context.device();
    const std::string what = "graphics pipeline '" + m_name + "'";
    const uint32_t max_push = context.device_info().limits.max_push_constants_size;
    if (m_layout.push_constant_bytes % 4 != 0 || m_layout.push_constant_bytes > max_push) {
        throw GpuError(what + ": " + std::to_string(m_layout.push_constant_bytes) +
                       " push-constant bytes (a multiple of 4, at most " +
                       std::to_string(max_push) + ")");
    }
    VkShaderModule modules[2] = {VK_NULL_HANDLE, VK_NULL_HANDLE};
    try {
        if (!m_layout.bindings.empty()) create_set_layout(device, what);
        create_pipeline_layout(device);
        modules[0] = create_module(device, vertex_spirv, what);
        modules[1] = create_module(device, fragment_spirv, what);
        m_pipeline = create_pipeline(device, m_layout, m_pipeline_layout, modules, m_name);
    } catch (...) {
        for (VkShaderModule module : modules) {
            if (module) vkDestroyShaderModule(device, module, nullptr);
        }
        release();
        throw;
    }
    // The pipeline keeps what it needs; the modules are only inputs.
    for (VkShaderModule module : modules)
        vkDestroyShaderModule(device, module, nullptr);
    context.set_debug_name(VK_OBJECT_TYPE_PIPELINE, uint64_t(m_pipeline), m_name);
}

void GraphicsPipeline::create_set_layout(VkDevice device, const std::string& what) {
    // Immutable: baked into the set layout, so draws bind only the images.
    m_sampler = create_nearest_sampler(device);
    std::vector<VkDescriptorSetLayoutBinding> bindings;
    for (uint32_t i = 0; i < m_layout.bindings.size(); ++i) {
        if (m_layout.bindings[i] != BindingType::sampled_image)
            throw GpuError(what + ": binding " + std::to_string(i) + " is not a sampled image");
        VkDescriptorSetLayoutBinding b{};
        b.binding = i;
        b.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
        b.descriptorCount = 1;
        b.stageFlags = VK_SHADER_STAGE_FRAGMENT_BIT;
        b.pImmutableSamplers = &m_sampler;
        bindings.push_back(b);
    }
    VkDescriptorSetLayoutCreateInfo set_info{};
    set_info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
    set_info.bindingCount = uint32_t(bindings.size());
    set_info.pBindings = bindings.data();
    vk_check(vkCreateDescriptorSetLayout(device, &set_info, nullptr, &m_set_layout),
             "vkCreateDescriptorSetLayout(" + m_name + ")");
}

void GraphicsPipeline::create_pipeline_layout(VkDevice device) {
    VkPushConstantRange push{};
    push.stageFlags = kPushStages;
    push.size = m_layout.push_constant_bytes;
    VkPipelineLayoutCreateInfo layout_info{};
    layout_info.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
    layout_info.setLayoutCount = m_set_layout ? 1 : 0;
    layout_info.pSetLayouts = &m_set_layout;
    layout_info.pushConstantRangeCount = push.size > 0 ? 1 : 0;
    layout_info.pPushConstantRanges = &push;
    vk_check(vkCreatePipelineLayout(device, &layout_info, nullptr, &m_pipeline_layout),
             "vkCreatePipelineLayout(" + m_name + ")");
}

GraphicsPipeline::~GraphicsPipeline() {
    release();
}

void GraphicsPipeline::release() noexcept {
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

void bind_images(CommandList& cmd, const GraphicsPipeline& pipeline,
                 std::span<const Image* const> images) {
    bind_image_set(cmd, pipeline, write_image_set(cmd, pipeline, images));
}

void bind_image_set(CommandList& cmd, const GraphicsPipeline& pipeline, VkDescriptorSet set) {
    if (!set) return;
    vkCmdBindDescriptorSets(cmd.handle(), VK_PIPELINE_BIND_POINT_GRAPHICS,
                            pipeline.pipeline_layout(), 0, 1, &set, 0, nullptr);
}

VkDescriptorSet write_image_set(CommandList& cmd, const GraphicsPipeline& pipeline,
                                std::span<const Image* const> images) {
    const std::vector<BindingType>& bindings = pipeline.layout().bindings;
    if (images.size() != bindings.size()) {
        throw GpuError("bind_images for '" + pipeline.name() +
                       "': " + std::to_string(images.size()) + " images for " +
                       std::to_string(bindings.size()) + " bindings");
    }
    if (images.empty()) return VK_NULL_HANDLE;
    const VkDescriptorSet set = cmd.context().allocate_transient_set(pipeline.set_layout());
    std::vector<VkDescriptorImageInfo> infos;
    infos.reserve(images.size());  // the writes point into it
    std::vector<VkWriteDescriptorSet> writes;
    for (uint32_t i = 0; i < images.size(); ++i) {
        if (!images[i]) throw GpuError("bind_images for '" + pipeline.name() + "': no image");
        infos.push_back({VK_NULL_HANDLE, images[i]->view(), VK_IMAGE_LAYOUT_GENERAL});
        VkWriteDescriptorSet write{};
        write.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
        write.dstSet = set;
        write.dstBinding = i;
        write.descriptorCount = 1;
        write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
        write.pImageInfo = &infos.back();
        writes.push_back(write);
    }
    vkUpdateDescriptorSets(cmd.context().device(), uint32_t(writes.size()), writes.data(), 0,
                           nullptr);
    return set;
}

namespace {

void bind(CommandList& cmd, const GraphicsPipeline& pipeline, const Buffer& vertices,
          std::span<const std::byte> push_constants) {
    if (push_constants.size() != pipeline.layout().push_constant_bytes) {
        throw GpuError("draw with '" + pipeline.name() +
                       "': " + std::to_string(push_constants.size()) +
                       " push-constant bytes, the layout has " +
                       std::to_string(pipeline.layout().push_constant_bytes));
    }
    const VkCommandBuffer handle = cmd.handle();
    vkCmdBindPipeline(handle, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.handle());
    const VkBuffer buffer = vertices.handle();
    const VkDeviceSize offset = 0;
    vkCmdBindVertexBuffers(handle, 0, 1, &buffer, &offset);
    if (!push_constants.empty()) {
        vkCmdPushConstants(handle, pipeline.pipeline_layout(), kPushStages, 0,
                           uint32_t(push_constants.size()), push_constants.data());
    }
}

}  // namespace

void set_cull_back(CommandList& cmd, const GraphicsPipeline& pipeline, bool cull) {
    if (!pipeline.layout().dynamic_cull)
        throw GpuError("set_cull_back with '" + pipeline.name() + "': its cull mode is fixed");
    vkCmdSetCullMode(cmd.handle(), cull ? VK_CULL_MODE_BACK_BIT : VK_CULL_MODE_NONE);
}

void draw(CommandList& cmd, const GraphicsPipeline& pipeline, const Buffer& vertices,
          std::span<const std::byte> push_constants, uint32_t first_vertex, uint32_t vertex_count) {
    bind(cmd, pipeline, vertices, push_constants);
    vkCmdDraw(cmd.handle(), vertex_count, 1, first_vertex, 0);
}

void draw_indexed(CommandList& cmd, const GraphicsPipeline& pipeline, const Buffer& vertices,
                  const Buffer& indices, std::span<const std::byte> push_constants,
                  std::span<const IndexRange> ranges) {
    if (!has(indices.usage(), BufferUsage::index))
        throw GpuError("draw_indexed with '" + pipeline.name() + "': not an index buffer");
    bind(cmd, pipeline, vertices, push_constants);
    vkCmdBindIndexBuffer(cmd.handle(), indices.handle(), 0, VK_INDEX_TYPE_UINT32);
    for (const IndexRange& r : ranges) {
        if (r.index_count > 0)
            vkCmdDrawIndexed(cmd.handle(), r.index_count, 1, r.first_index, 0, 0);
    }
}

}  // namespace mvpl::gpu
