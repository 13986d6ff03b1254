#pragma once
// Vulkan handle types without <vulkan/vulkan.h>, so that public engine/gpu headers can hold and
// hand out handles while the rest of mvpl (tools/, sampler/, tests) never sees the Vulkan API.
//
// The typedefs repeat vulkan_core.h's exactly (a repeated identical typedef is legal C++), which
// holds wherever non-dispatchable handles are pointers, i.e. on every 64-bit target;
// vk_check.cpp static_asserts that, so a 32-bit build fails loudly instead of mismatching.

// NOLINTBEGIN(modernize-use-using): the spelling must match vulkan_core.h.
typedef struct VkInstance_T* VkInstance;
typedef struct VkPhysicalDevice_T* VkPhysicalDevice;
typedef struct VkDevice_T* VkDevice;
typedef struct VkQueue_T* VkQueue;
typedef struct VkCommandBuffer_T* VkCommandBuffer;
typedef struct VkCommandPool_T* VkCommandPool;
typedef struct VkFence_T* VkFence;
typedef struct VkDeviceMemory_T* VkDeviceMemory;
typedef struct VkBuffer_T* VkBuffer;
typedef struct VkImage_T* VkImage;
typedef struct VkImageView_T* VkImageView;
typedef struct VkQueryPool_T* VkQueryPool;
typedef struct VkShaderModule_T* VkShaderModule;
typedef struct VkPipeline_T* VkPipeline;
typedef struct VkPipelineLayout_T* VkPipelineLayout;
typedef struct VkDescriptorSetLayout_T* VkDescriptorSetLayout;
typedef struct VkDescriptorPool_T* VkDescriptorPool;
typedef struct VkDescriptorSet_T* VkDescriptorSet;
typedef struct VkSampler_T* VkSampler;
typedef struct VkDebugUtilsMessengerEXT_T* VkDebugUtilsMessengerEXT;
// NOLINTEND(modernize-use-using)
