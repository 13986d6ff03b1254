// The whole VPL pipeline — Monte Carlo light paths on the CPU, shading on the GPU — against
// independent answers: the CPU oracle with exact visibility (same VPLs), the Mitsuba 2 Cornell box
// and the analytic direct light of a point light (other scales: tests/stability).
#include <gtest/gtest.h>

#include "engine/core/image_metrics.h"
#include "engine/light/light_sampler.h"
#include "engine/reference/path_tracer.h"
#include "engine/reference/vpl_gather.h"
#include "engine/render/vpl_renderer.h"
#include "engine/scene/camera.h"
#include "engine/scene/scene_loader.h"
#include "engine/trace/accel.h"
#include "tests/gpu/gpu_test.h"
#include "tests/support/lit_plane.h"
#include "tests/support/scene_builder.h"
#include "tests/support/vpl_render.h"

namespace mvpl::render {
namespace {

using VplPipelineTest = gpu::testing::GpuTest;
using test::monte_carlo_vpls;

Image gpu_render(gpu::Context& context, const scene::Scene& s, const light::VplSet& vpls, int res,
                 int shadow_res, float clamp) {
    return test::gpu_render(context, s, vpls,
                            {.res = res, .shadow_res = shadow_res, .clamp = clamp});
}

Image oracle_render(const scene::Scene& s, const light::VplSet& vpls, int res, float clamp) {
    return test::oracle_render(s, vpls, {.res = res, .clamp = clamp});
}

// GPU against the oracle with the same VPLs: they differ only where the shadow cube's nearest
// texel decides visibility differently from Embree, i.e. for pixel·VPL pairs whose shadow
// boundary passes within about one texel (1.25 texel angles, 2/res each; see test_shadows.cpp)
// of the receiver's direction. A pair in that band can be wrong, and a pixel's relative error is
// at most the share of its light that comes through such pairs; if every pixel's light came
// through one VPL the relMSE would be the probability of the band, 1.25 · 2/res. That worst case
// is the bound. The error must also fall with the resolution (the band narrows as 1/res).
TEST_F(VplPipelineTest, GpuAgreesWithTheOracleWithinTheShadowMapResolution) {
    for (const char* path : {"/cornell-box/cbox.gltf", "/two-room/two-room.gltf"}) {
        SCOPED_TRACE(path);
        const scene::Scene s = scene::load_scene(std::string(MVPL_ASSETS_DIR) + path);
        const light::VplSet vpls = monte_carlo_vpls(s, 48, 6, 3);
        const Image oracle = oracle_render(s, vpls, 64, 0.05f);
        const double coarse =
            compare_images(gpu_render(context(), s, vpls, 64, 128, 0.05f), oracle).rel_mse;
        const double fine =
            compare_images(gpu_render(context(), s, vpls, 64, 256, 0.05f), oracle).rel_mse;
        EXPECT_LT(fine, 1.25 * 2.0 / 256.0);
        EXPECT_LT(fine, coarse) << "coarse " << coarse;
        RecordProperty(std::string("coarse") + path, std::to_string(coarse));
        EXPECT_GT(oracle.mean().r, 0.0f);
        RecordProperty(std::string("relmse") + path, std::to_string(fine));
    }
}

// With clamping off, the VPL estimate is unbiased: the Cornell box at max depth 6 matches Mitsuba
// 2. The GPU samples the emission seen directly at one sub-pixel position per batch (≈90 here),
// which still miscounts the area of the luminaire at low resolution (half the image's mean comes
// from a few rows of pixels); that term, taken at the same positions, is swapped for the path
// tracer's box-filtered emission at depth 1 (the correction of tests/sampler/test_vpl_image.cpp).
// 1024 paths leave ≈2900 VPLs, whose standard error on the mean is under 1% (measured between
// seeds), well inside the 3% the acceptance asks for.
TEST_F(VplPipelineTest, CornellBoxMatchesMitsubaWithClampingOff) {
    const scene::Scene s = scene::load_scene(MVPL_ASSETS_DIR "/cornell-box/cbox.gltf");
    constexpr int kRes = 128;
    const light::VplSet vpls = monte_carlo_vpls(s, 1024, 6, 1);
    const Rgb with_vpls = gpu_render(context(), s, vpls, kRes, 128, 0.0f).mean();
    const Rgb emitted_centres =
        test::emission_at_positions(s, vpls.vpls.size(), {.res = kRes}).mean();
    const trace::Accel accel(s);
    const light::LightSampler lights(s);
    reference::PathTracerOptions p;
    p.width = p.height = kRes;
    p.spp = 16;
    p.max_depth = 1;
    p.quiet = true;
    const Rgb emitted_box = reference::PathTracer(s, accel, lights).render(p).mean();
    const Rgb mean = with_vpls - emitted_centres + emitted_box;
    const Rgb ref = read_exr(MVPL_ASSETS_DIR "/cornell-box/ref-cbox-d6-4096.exr").mean();
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(mean[c] / ref[c], 1.0, 0.03) << "channel " << c;
}

// Point lights only, max depth 2: the sampler leaves Point VPLs whose powers sum to the intensity,
// and the GPU image equals the analytic direct light at pixel centres.
TEST_F(VplPipelineTest, PointLightDirectLightIsAnalytic) {
    const scene::Light l = test::example_point_light();
    const scene::Scene s = test::make_lit_plane(l);
    const light::VplSet set = monte_carlo_vpls(s, 16, 2, 0);
    const std::vector<light::Vpl>& vpls = set.vpls;
    ASSERT_FALSE(vpls.empty());
    const Image image = gpu_render(context(), s, set, 32, 64, 0.0f);
    double worst = 0.0;
    for (int y = 0; y < 32; ++y) {
        for (int x = 0; x < 32; ++x) {
            const scene::CameraRay r =
                scene::generate_camera_ray(s.camera, 32, 32, Vec2(x + 0.5f, y + 0.5f));
            const Vec3 p = r.origin + (-r.origin.y / r.direction.y) * r.direction;
            const float expected = test::lit_plane_radiance(l, p).g;
            worst = std::max(worst, double(std::abs(image.at(x, y).g - expected) / expected));
        }
    }
    EXPECT_LT(worst, 1e-3);
}

}  // namespace
}  // namespace mvpl::render
