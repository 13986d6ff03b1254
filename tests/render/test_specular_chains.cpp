// Specular chains on the GPU (issue 15): the shading pass lights glossy pixels at the rough end
// of their camera paths, which the chain layer traces on the CPU with the oracle's random
// numbers. The GPU image equals the oracle's within the shadow-map bound of the other
// GPU-vs-oracle tests; without chains it is far from it (the sphere black); and a scene without
// glossy materials gets neither chain code nor chain rays.
#include <gtest/gtest.h>

#include <string>

#include "engine/core/image.h"
#include "engine/core/image_metrics.h"
#include "engine/render/shader_program.h"
#include "engine/render/vpl_renderer.h"
#include "engine/scene/scene_loader.h"
#include "engine/trace/accel.h"
#include "tests/gpu/gpu_test.h"
#include "tests/support/glass_slab.h"
#include "tests/support/mirror_box.h"
#include "tests/support/vpl_render.h"

namespace mvpl::render {
namespace {

struct OracleAndGpu {
    Image oracle;
    Image gpu;
};

class SpecularChainsTest : public gpu::testing::GpuTest {
protected:
    // The GPU image against the oracle's with chains, within the bound below; without chains the
    // GPU image must be far from it (> 4 × the bound). Returns the two images with chains.
    OracleAndGpu expect_gpu_equals_oracle_with_chains(const scene::Scene& s,
                                                      const light::VplSet& vpls,
                                                      const test::VplRenderSettings& settings,
                                                      const char* what);
};

// The bound of tests/render/test_vpl_pipeline.cpp: GPU and oracle differ only where the shadow
// cube's nearest texel decides visibility differently from Embree, a band of about 1.25 texel
// angles (2/res each) around each shadow boundary: relMSE ≤ 1.25 · 2/res. The chains themselves
// are the same paths on both sides (light::chain_rng), so they add nothing.
OracleAndGpu SpecularChainsTest::expect_gpu_equals_oracle_with_chains(
    const scene::Scene& s, const light::VplSet& vpls, const test::VplRenderSettings& settings,
    const char* what) {
    OracleAndGpu out{test::oracle_render(s, vpls, settings),
                     test::gpu_render(context(), s, vpls, settings)};
    const double bound = 1.25 * 2.0 / 256.0;  // the shadow-map band above, 256² faces
    const double error = compare_images(out.gpu, out.oracle).rel_mse;
    EXPECT_LT(error, bound) << what;
    RecordProperty(std::string("relmse_") + what, std::to_string(error));
    std::printf("GPU vs oracle with chains (%s): relMSE %.3g (bound %.3g)\n", what, error, bound);

    test::VplRenderSettings plain = settings;
    plain.chain_roughness = -1.0f;
    const double without =
        compare_images(test::gpu_render(context(), s, vpls, plain), out.oracle).rel_mse;
    EXPECT_GT(without, 4.0 * bound) << what;
    RecordProperty(std::string("relmse_without_chains_") + what, std::to_string(without));
    return out;
}

TEST_F(SpecularChainsTest, TheGpuEqualsTheOracleOnAMirrorSphere) {
    const scene::Scene s = test::make_mirror_box();
    const light::VplSet vpls = test::monte_carlo_vpls(s, 256, 4, 5);
    test::VplRenderSettings settings{.res = 48, .shadow_res = 256, .clamp = 0.05f};
    settings.chain_roughness = light::kDefaultChainRoughness;
    settings.chain_max_depth = 4;
    settings.chain_seed = 9;
    settings.chain_emission_samples = 4;  // the area light's reflection, sampled alike
    expect_gpu_equals_oracle_with_chains(s, vpls, settings, "mirror");
    // With interleaving: test_interleave_chains.cpp.
}

// Glass (KHR_materials_transmission): the chain layer continues camera paths through the sheet
// and the GPU shades the wall behind it, equal to the oracle (which test_glass_slab.cpp checks
// against the path tracer) within the same shadow-map bound; without chains the sheet shows only
// its reflection, far from it.
TEST_F(SpecularChainsTest, TheGpuEqualsTheOracleThroughAGlassSheet) {
    const scene::Scene s = test::make_glass_slab(Rgb(0.95f, 0.85f, 0.7f));
    const light::VplSet vpls = test::monte_carlo_vpls(s, 256, 3, 5);
    test::VplRenderSettings settings{.res = 48, .shadow_res = 256, .clamp = 0.05f};
    settings.chain_roughness = light::kDefaultChainRoughness;
    settings.chain_max_depth = 3;
    settings.chain_seed = 3;
    // Four sub-pixel samples of the light the chains meet (pixel_chain_emission), as both
    // renderers draw them: the same random numbers, the same records.
    settings.chain_emission_samples = 4;
    expect_gpu_equals_oracle_with_chains(s, vpls, settings, "glass");
}

// Leave out what a scene does not need: the Cornell box (diffuse) with chains asked for gets a
// shading program without chain code and traces no chain ray.
TEST_F(SpecularChainsTest, ADiffuseSceneHasNoChainCodeAndTracesNoChainRays) {
    const scene::Scene s =
        scene::load_scene(std::string(MVPL_SOURCE_DIR) + "/assets/cornell-box/cbox.gltf");
    const SceneShaders shaders = generate_scene_shaders(s, ShaderOptions{});
    EXPECT_FALSE(shaders.features.specular_chains);
    EXPECT_EQ(shaders.shading_comp.source.find("ChainRecord"), std::string::npos);
    const trace::Accel accel(s);
    VplRenderer renderer(context(), s, &accel);
    RenderOptions o;
    o.width = o.height = 16;
    o.chains.max_roughness = light::kDefaultChainRoughness;
    const light::VplSet vpls = test::monte_carlo_vpls(s, 8, 3, 1);
    const uint64_t rays = accel.ray_count();
    renderer.render(vpls, o);
    EXPECT_EQ(renderer.timings().chain_rays, 0u);
    EXPECT_EQ(accel.ray_count(), rays);

    // The mirror box does get them.
    const scene::Scene m = test::make_mirror_box();
    const trace::Accel mirror_accel(m);
    VplRenderer mirror_renderer(context(), m, &mirror_accel);
    mirror_renderer.render(test::monte_carlo_vpls(m, 8, 3, 1), o);
    EXPECT_GT(mirror_renderer.timings().chain_rays, 0u);
}

}  // namespace
}  // namespace mvpl::render
