// Mitsuba's `mask` with a textured opacity over a BSDF with its own texture (issue 16,
// tests/data/mitsuba/masked_textured.xml): the opacity bitmap becomes the alpha
// (scene::Material::opacity_texture) beside the reflectance bitmap, on the GPU as on the CPU.
#include <gtest/gtest.h>

#include <string>

#include "engine/core/image_metrics.h"
#include "engine/scene/scene_loader.h"
#include "tests/gpu/gpu_test.h"
#include "tests/support/vpl_render.h"

namespace mvpl::render {
namespace {

using MitsubaMaskTest = gpu::testing::GpuTest;

const std::string kScene = std::string(MVPL_TEST_DATA_DIR) + "/mitsuba/masked_textured.xml";

// Same bound and reasoning as test_mitsuba_bsdfs.cpp: GPU and oracle shade the same VPLs with the
// same node evaluators and the same hashed transparency, and differ only where the shadow cube's
// nearest texel decides visibility otherwise than Embree, at most that band's probability,
// 1.25 · 2/shadow_res. The opacity is 0 or 1 at every texel (nearest filtered), so the hashed
// transparency keeps or cuts each hit alike on both sides (a fractional alpha would make the
// point light's shadow on the wall a per-pixel coin toss on each side). Without the opacity
// texture the quad is opaque (its clear corners then hide the wall and shadow it): that image
// must be beyond four times the bound, or the test would not see the mask. Measured: 1.1e-3;
// without the opacity 0.58.
TEST_F(MitsubaMaskTest, TexturedOpacityOverATexturedBsdfAgreesWithTheOracle) {
    const scene::Scene s = scene::load_scene(kScene);
    const scene::Material& leaf = s.materials.at(size_t(s.meshes.at(0).material));
    ASSERT_TRUE(leaf.base_color_texture.valid());
    ASSERT_TRUE(leaf.opacity_texture.valid());
    constexpr int kShadowRes = 256;
    const double bound = 1.25 * 2.0 / kShadowRes;
    const light::VplSet vpls = test::monte_carlo_vpls(s, 32, 2, 1);
    const test::VplRenderSettings settings{.res = 32, .shadow_res = kShadowRes};
    const Image oracle = test::oracle_render(s, vpls, settings);
    const Image gpu = test::gpu_render(context(), s, vpls, settings);
    const double error = compare_images(gpu, oracle).rel_mse;
    EXPECT_LT(error, bound);
    scene::Scene opaque = s;
    opaque.materials[size_t(s.meshes[0].material)].opacity_texture = {};
    const double unmasked =
        compare_images(test::gpu_render(context(), opaque, vpls, settings), oracle).rel_mse;
    EXPECT_GT(unmasked, 4.0 * bound);
    RecordProperty("relmse", std::to_string(error));
    RecordProperty("relmse_without_opacity", std::to_string(unmasked));
}

}  // namespace
}  // namespace mvpl::render
