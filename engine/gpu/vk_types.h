#pragma once
// Internal: mvpl's Vulkan-free enums → Vulkan's. Includes <vulkan/vulkan.h>.
#include <vulkan/vulkan.h>

#include "engine/gpu/compute_pipeline.h"
#include "engine/gpu/format.h"

namespace mvpl::gpu {

VkFormat to_vk_format(Format format);                      // format.cpp
VkImageAspectFlags aspect_of(Format format);               // format.cpp
VkDescriptorType to_vk_descriptor_type(BindingType type);  // compute_pipeline.cpp
// Nearest filtering, clamp to edge, no mip levels: the immutable sampler of the pipelines'
// sampled images (compute_pipeline.cpp).
VkSampler create_nearest_sampler(VkDevice device);

}  // namespace mvpl::gpu
