// Precision at the edges: near-mirror BRDFs at grazing angles, a VPL touching its receiver with
// clamping off, and 10⁵ VPLs summed in float on the GPU against a double sum on the CPU.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "engine/core/image_metrics.h"
#include "engine/core/rng.h"
#include "engine/render/g_buffer_pass.h"
#include "engine/render/vpl_renderer.h"
#include "tests/gpu/gpu_test.h"
#include "tests/stability/stability_scenes.h"
#include "tests/support/lit_plane.h"
#include "tests/support/scene_builder.h"
#include "tests/support/vpl_render.h"

namespace mvpl {
namespace {

using PrecisionTest = gpu::testing::GpuTest;

int count_non_finite(const Image& image) {
    int count = 0;
    for (const Rgb& c : image.pixels())
        count += std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b) ? 0 : 1;
    return count;
}

// Roughness 10⁻³ (the closure's smallest α) seen and lit at 85–89° from the normal: every value
// finite, and the GPU equal to the oracle within the shadow-map bound of the pipeline test
// (1.25 · 2/res, tests/render/test_vpl_pipeline.cpp) — which also bounds the image, since the
// oracle's is bounded by its own finite sums.
TEST_F(PrecisionTest, NearMirrorAtGrazingAnglesAgreesWithTheOracle) {
    const scene::Scene s = test::make_near_mirror_scene();
    const light::VplSet vpls = test::monte_carlo_vpls(s, 96, 6, 7);
    const test::VplRenderSettings settings{.res = 64, .shadow_res = 256, .clamp = 0.05f};
    const Image gpu = test::gpu_render(context(), s, vpls, settings);
    const Image oracle = test::oracle_render(s, vpls, settings);
    EXPECT_EQ(count_non_finite(gpu), 0);
    EXPECT_EQ(count_non_finite(oracle), 0);
    EXPECT_GT(oracle.mean().g, 0.0f);
    const ImageError error = compare_images(gpu, oracle);
    EXPECT_LT(error.rel_mse, 1.25 * 2.0 / 256.0);
    RecordProperty("relmse", std::to_string(error.rel_mse));
}

// Point VPLs 10⁻⁷ m above and exactly at the point a pixel sees, and a surface VPL lying there,
// clamping off: the 1/d² singularity is reached (d² ≈ 10⁻¹⁴ and 0) and every pixel must stay
// finite (resolve() throws NonFiniteError otherwise), with and without shadows, on the GPU and in
// the oracle.
TEST_F(PrecisionTest, VplTouchingItsReceiverWithClampingOffIsFinite) {
    const scene::Scene s = test::make_lit_plane(test::example_point_light());
    constexpr int kRes = 32;
    render::VplRenderer renderer(context(), s);
    render::RenderOptions o;
    o.width = o.height = kRes;
    o.shadow_resolution = 64;
    o.clamp = 0.0f;
    renderer.begin(s.camera, o);
    const std::vector<float> positions =
        renderer.g_buffer().download_as<float>(render::kGBufferPosition, 1);
    const size_t centre = 4 * (size_t(kRes / 2) * kRes + kRes / 2);
    const Vec3 p(positions[centre], positions[centre + 1], positions[centre + 2]);
    ASSERT_NEAR(p.y, 0.0f, 1e-6f);

    std::vector<light::Vpl> vpls;
    light::Vpl point;
    point.type = light::VplType::Point;
    point.power = Rgb(1.0f);
    for (const float height : {1e-7f, 0.0f}) {
        point.position = p + Vec3(0.0f, height, 0.0f);
        vpls.push_back(point);
    }
    light::Vpl surface;
    surface.type = light::VplType::Surface;
    surface.position = p;
    surface.normal = surface.shading_normal = Vec3(0, 1, 0);
    surface.wi = glm::normalize(Vec3(0.2f, 1.0f, 0.0f));
    surface.power = Rgb(1.0f);
    surface.closure.base_color = Rgb(0.5f);
    surface.closure.metallic = 0.0f;
    surface.closure.roughness = 0.5f;
    vpls.push_back(surface);
    for (const bool shadows : {true, false}) {
        o.shadows = shadows;
        renderer.begin(s.camera, o);
        renderer.accumulate(vpls);
        Image image;
        EXPECT_NO_THROW(image = renderer.resolve(1.0)) << "shadows " << shadows;
        EXPECT_EQ(count_non_finite(image), 0);
    }
    EXPECT_EQ(count_non_finite(test::oracle_render(s, {vpls}, {.res = kRes, .clamp = 0.0f})), 0);
}

// 10⁵ point VPLs with powers over six orders of magnitude, unshadowed, summed in float by the GPU
// (B per dispatch in a register, then added into the RGBA32F image) against a double sum of the
// same formula on the CPU at the G-buffer's own positions. For positive terms float summation
// errs by at most (n − 1)·u of the sum (u = 2⁻²⁴, Higham 2002 §4.2): B − 1 within a batch plus
// n/B − 1 across batches. Each term's own evaluation (≈ 20 float operations; Vulkan allows
// 2.5 ulp for division and inversesqrt) adds at most ≈ 100 u. With n = 10⁵, B = 256:
// (255 + 390 + 100)·u ≈ 4.4·10⁻⁵; the test allows 5·10⁻⁵.
TEST_F(PrecisionTest, HundredThousandVplsInFloatMatchADoubleSum) {
    constexpr int kRes = 16, kCount = 100000, kBatch = 256;
    const scene::Scene s = test::make_lit_plane(test::example_point_light());
    Rng rng(5, 0);
    std::vector<light::Vpl> vpls(kCount);
    for (light::Vpl& v : vpls) {
        v.type = light::VplType::Point;
        v.position = Vec3(-2.0f + 4.0f * rng.next_float(), 0.5f + 1.5f * rng.next_float(),
                          -2.0f + 4.0f * rng.next_float());
        const float power = std::pow(10.0f, -3.0f + 6.0f * rng.next_float()) / float(kCount);
        v.power = Rgb(power, 0.5f * power, 0.25f * power);
    }
    render::VplRenderer renderer(context(), s);
    render::RenderOptions o;
    o.width = o.height = kRes;
    o.batch = kBatch;
    o.shadows = false;
    o.clamp = 0.0f;
    o.jitter = false;  // one G-buffer: every VPL at the positions read back below
    renderer.begin(s.camera, o);
    renderer.accumulate(vpls);
    const Image gpu = renderer.resolve(1.0);
    const std::vector<float> positions =
        renderer.g_buffer().download_as<float>(render::kGBufferPosition, 1);

    double worst = 0.0;
    for (int i = 0; i < kRes * kRes; ++i) {
        ASSERT_GT(positions[4 * i + 3], 0.0f) << "the plane fills the view";
        const Vec3 p(positions[4 * i], positions[4 * i + 1], positions[4 * i + 2]);
        // vpl.h's Point contribution on the Lambertian plane (normal +y): P·(ρ/π)·cos θ'/d².
        double sum[3] = {0.0, 0.0, 0.0};
        for (const light::Vpl& v : vpls) {
            const double dx = double(v.position.x) - p.x, dy = double(v.position.y) - p.y,
                         dz = double(v.position.z) - p.z;
            const double d2 = dx * dx + dy * dy + dz * dz;
            const double g = (test::kLitPlaneAlbedo / kPi) * (dy / std::sqrt(d2)) / d2;
            for (int c = 0; c < 3; ++c)
                sum[c] += double(v.power[c]) * g;
        }
        for (int c = 0; c < 3; ++c)
            worst = std::max(worst, std::abs(double(gpu.pixels()[size_t(i)][c]) - sum[c]) / sum[c]);
    }
    EXPECT_LT(worst, 5e-5);
    RecordProperty("worst_relative_error", std::to_string(worst));
}

}  // namespace
}  // namespace mvpl
