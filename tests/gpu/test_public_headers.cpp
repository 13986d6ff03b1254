// The engine/gpu headers that tools/, sampler/ and tests include must not drag in Vulkan or
// glslang: this file includes all of them first and fails to compile if either appears.
#include "engine/gpu/buffer.h"
#include "engine/gpu/command_list.h"
#include "engine/gpu/compute_pipeline.h"
#include "engine/gpu/context.h"
#include "engine/gpu/device_info.h"
#include "engine/gpu/embedded_shaders.h"
#include "engine/gpu/format.h"
#include "engine/gpu/gpu_error.h"
#include "engine/gpu/gpu_timer.h"
#include "engine/gpu/graphics_pipeline.h"
#include "engine/gpu/image.h"
#include "engine/gpu/memory.h"
#include "engine/gpu/shader_compiler.h"
#include "engine/gpu/spirv_cache.h"
#include "engine/gpu/swapchain.h"
#include "engine/gpu/validation.h"
#include "engine/gpu/vk_fwd.h"

#ifdef VULKAN_CORE_H_
#error "a public engine/gpu header includes <vulkan/vulkan.h>"
#endif
#ifdef _COMPILER_INTERFACE_INCLUDED_
#error "a public engine/gpu header includes glslang"
#endif

#include <gtest/gtest.h>

namespace mvpl::gpu {
namespace {

TEST(PublicHeaders, AreFreeOfVulkanAndGlslang) {
    // The check is the #error above; this only gives the file a test to show in the list.
    EXPECT_EQ(bytes_per_pixel(Format::rgba32_float), 16u);
    EXPECT_EQ(bytes_per_pixel(Format::r32_float), 4u);
}

}  // namespace
}  // namespace mvpl::gpu
