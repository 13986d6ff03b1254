// engine/render's headers are included by tools/ and tests, which must not see Vulkan: this file
// includes all of them first and fails to compile if <vulkan/vulkan.h> comes along.
#include "engine/gpu/graphics_pipeline.h"
#include "engine/render/g_buffer_pass.h"
#include "engine/render/gpu_vpl.h"
#include "engine/render/scene_geometry.h"
#include "engine/render/shading_pass.h"
#include "engine/render/shadow_pass.h"
#include "engine/render/vpl_renderer.h"

#ifdef VULKAN_CORE_H_
#error "a public engine/render header includes <vulkan/vulkan.h>"
#endif

#include <gtest/gtest.h>

namespace mvpl::render {
namespace {

TEST(RenderPublicHeaders, AreFreeOfVulkan) {
    SUCCEED();
}

}  // namespace
}  // namespace mvpl::render
