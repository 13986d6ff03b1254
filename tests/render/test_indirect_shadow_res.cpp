// Smaller shadow cubes for indirect VPLs (issue 14, "many small maps", rasterised:
// RenderOptions::indirect_shadow_resolution): VPLs of path length ≥ 1 draw their cubes into the
// first rows and columns of their layers, and the shading pass reads them at that resolution.
// Emitter VPLs must not change at all; the whole image must stay within the shadow-map bound of
// the coarser faces against the oracle.
#include <gtest/gtest.h>

#include "engine/core/image_metrics.h"
#include "engine/render/vpl_renderer.h"
#include "engine/scene/scene_loader.h"
#include "tests/gpu/gpu_test.h"
#include "tests/support/vpl_render.h"

namespace mvpl::render {
namespace {

using IndirectShadowResTest = gpu::testing::GpuTest;

size_t differing_pixels(const Image& a, const Image& b) {
    size_t n = 0;
    for (size_t i = 0; i < a.pixels().size(); ++i)
        n += a.pixels()[i] != b.pixels()[i] ? 1 : 0;
    return n;
}

TEST_F(IndirectShadowResTest, EmitterVplsKeepTheirFaces) {
    const scene::Scene s = scene::load_scene(MVPL_ASSETS_DIR "/cornell-box/cbox.gltf");
    const light::VplSet direct = test::monte_carlo_vpls(s, 32, 2, 4);  // emitter VPLs only
    VplRenderer renderer(context(), s);
    RenderOptions o;
    o.width = o.height = 48;
    o.shadow_resolution = 128;
    const Image full = renderer.render(direct, o);
    o.indirect_shadow_resolution = 16;
    EXPECT_EQ(differing_pixels(renderer.render(direct, o), full), 0u);
}

// The band argument of test_vpl_pipeline's GpuAgreesWithTheOracleWithinTheShadowMapResolution:
// a pixel·VPL pair can be wrong only where a shadow boundary passes within 1.25 texel angles of
// the receiver's direction, 2/res each, so the relMSE stays below the band's probability at the
// coarsest faces drawn, 1.25 · 2/64 here. The faces do change the indirect shadows.
TEST_F(IndirectShadowResTest, CornellBoxStaysWithinTheCoarseFacesBound) {
    const scene::Scene s = scene::load_scene(MVPL_ASSETS_DIR "/cornell-box/cbox.gltf");
    const light::VplSet vpls = test::monte_carlo_vpls(s, 48, 6, 3);
    const Image oracle = test::oracle_render(s, vpls, {.res = 64, .clamp = 0.05f});
    VplRenderer renderer(context(), s);
    RenderOptions o;
    o.width = o.height = 64;
    o.shadow_resolution = 256;
    o.clamp = 0.05f;
    const Image full = renderer.render(vpls, o);
    o.indirect_shadow_resolution = 64;
    const Image coarse = renderer.render(vpls, o);
    EXPECT_GT(differing_pixels(coarse, full), 0u);
    const double error = compare_images(coarse, oracle).rel_mse;
    EXPECT_LT(error, 1.25 * 2.0 / 64.0);
    RecordProperty("relmse_full", std::to_string(compare_images(full, oracle).rel_mse));
    RecordProperty("relmse_indirect_64", std::to_string(error));
}

}  // namespace
}  // namespace mvpl::render
