// Interleaved sampling (issue 14, Keller & Heidrich 2001; shaders/shared/interleave.h): each
// pixel of a K×K block shades 1/K² of a batch, a geometry-aware filter restores the sum. On a
// single plane the filter accepts every neighbour, so the image must equal the oracle's
// unfiltered one up to where in the window each VPL was evaluated; on the Cornell box the GPU
// must agree with the oracle that reproduces the same assignment and filter.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "engine/core/image_metrics.h"
#include "engine/scene/scene_loader.h"
#include "tests/gpu/gpu_test.h"
#include "tests/support/scene_builder.h"
#include "tests/support/vpl_render.h"

namespace mvpl::render {
namespace {

using InterleaveTest = gpu::testing::GpuTest;

constexpr int kRes = 48;

// A diffuse plane that fills the view, seen from above through a narrow field of view, so that
// a filter window's footprint is small against the VPLs' distances.
scene::Scene plane_scene() {
    scene::Scene s;
    s.materials = {test::diffuse_material(Rgb(0.5f, 0.6f, 0.7f))};
    s.meshes.push_back(test::make_quad(Vec3(-50, 0, -50), Vec3(0, 0, 100), Vec3(100, 0, 0), 0));
    s.camera = test::look_at(Vec3(0.0f, 6.0f, 1.0f), Vec3(0, 0, 0), 0.1f);
    s.has_camera = true;
    return s;
}

// Point VPLs and downward-facing diffuse surface VPLs above the plane.
std::vector<light::Vpl> vpls_above(int count) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<light::Vpl> vpls;
    for (int i = 0; i < count; ++i) {
        light::Vpl v;
        v.type = i % 2 == 0 ? light::VplType::Point : light::VplType::Surface;
        v.position = Vec3(3.0f * u(rng) - 1.5f, 1.5f + 1.5f * u(rng), 3.0f * u(rng) - 1.5f);
        v.normal = v.shading_normal = Vec3(0, -1, 0);
        v.wi = glm::normalize(Vec3(u(rng) - 0.5f, -1.0f, u(rng) - 0.5f));
        v.power = Rgb(0.5f + u(rng), 0.5f + u(rng), 0.5f + u(rng));
        vpls.push_back(v);
    }
    return vpls;
}

// The first and last column (or row) of pixel x's filter window (interleave.h: centred, K or
// K + 1 wide, moved inwards at the border).
std::pair<int, int> window(int x, int k, int size) {
    const int r = k / 2;
    const int c = std::max(std::min(x, size - 1 - r), r);
    return {std::max(c - r, 0), std::min(c + r, size - 1)};
}

// On a plane every neighbour is accepted, and each class's weights in a window sum to 1, so the
// filtered pixel is Σ_i Σ_{q of class(i)} w_q c_i(q): for each VPL i a convex combination of its
// contribution c_i over the window. It therefore lies in [Σ_i min_W c_i, Σ_i max_W c_i], which
// the oracle's single-VPL images give exactly (an unoccluded plane: no shadow-map error), and
// which holds the oracle's unfiltered Σ_i c_i(p) too. Beyond it only float rounding: each
// contribution is a handful of float operations in either renderer (≈1e-6 relative), summed over
// 16 VPLs and divided by the filter's weight sum; 1e-4 relative leaves a factor of 10 over that.
TEST_F(InterleaveTest, OnAPlaneTheFilteredImageIsTheUnfilteredOne) {
    const scene::Scene s = plane_scene();
    const std::vector<light::Vpl> vpls = vpls_above(16);
    test::VplRenderSettings settings{.res = kRes, .shadow_res = 128, .clamp = 0.0f, .batch = 16};
    settings.jitter = false;  // one set of pixel positions for the single-VPL images too
    std::vector<Image> single;
    for (const light::Vpl& v : vpls)
        single.push_back(test::oracle_render(s, {{v}, 1.0}, settings));
    const Image unfiltered = test::oracle_render(s, {vpls, 1.0}, settings);
    for (const int k : {2, 3, 4}) {
        SCOPED_TRACE(k);
        settings.interleave = k;
        const Image gpu = test::gpu_render(context(), s, {vpls, 1.0}, settings);
        int outside = 0;
        double width = 0.0;
        for (int y = 0; y < kRes; ++y) {
            for (int x = 0; x < kRes; ++x) {
                const auto [x0, x1] = window(x, k, kRes);
                const auto [y0, y1] = window(y, k, kRes);
                Rgb lo(0.0f), hi(0.0f);
                for (const Image& one : single) {
                    Rgb mn(1e30f), mx(0.0f);
                    for (int qy = y0; qy <= y1; ++qy) {
                        for (int qx = x0; qx <= x1; ++qx) {
                            mn = glm::min(mn, one.at(qx, qy));
                            mx = glm::max(mx, one.at(qx, qy));
                        }
                    }
                    lo += mn;
                    hi += mx;
                }
                const Rgb g = gpu.at(x, y);
                const Rgb u = unfiltered.at(x, y);
                for (int c = 0; c < 3; ++c) {
                    const float tol = 1e-4f * hi[c];
                    ASSERT_GE(u[c], lo[c] - tol);  // the bound holds the unfiltered pixel
                    ASSERT_LE(u[c], hi[c] + tol);
                    if (g[c] < lo[c] - tol || g[c] > hi[c] + tol) ++outside;
                }
                width += double(hi.g - lo.g) / std::max(double(hi.g), 1e-30);
            }
        }
        EXPECT_EQ(outside, 0);
        // The bound is narrow enough to catch a filter that drops or doubles a class of VPLs,
        // which moves a pixel by about 1/K² of its value.
        width /= double(kRes * kRes);
        EXPECT_LT(width, 1.0 / double(k * k)) << "mean relative width of the bound";
        EXPECT_GT(unfiltered.mean().g, 0.0f);
        RecordProperty("mean_width_k" + std::to_string(k), std::to_string(width));
    }
}

// The Cornell box: where the filter rejects neighbours (edges, corners, the boxes' silhouettes)
// the interleaved image is another estimate than the unfiltered one, so the GPU is compared with
// the oracle that reproduces the assignment and the filter (interleaved_gather.h). The two
// differ where the shadow map decides visibility differently from Embree, the band of
// test_vpl_pipeline's GpuAgreesWithTheOracleWithinTheShadowMapResolution (1.25 texel angles of
// 2/res each): a pixel's value is still a positive combination of pixel·VPL pairs, so its
// relative error stays at most the share of its light through pairs in the band, and the
// relMSE at most that band's probability, 1.25 · 2/res. The filter's decisions agree: the box's
// surfaces are planes that meet at right angles, far from the acceptance thresholds.
TEST_F(InterleaveTest, CornellBoxAgreesWithTheInterleavedOracle) {
    const scene::Scene s = scene::load_scene(MVPL_ASSETS_DIR "/cornell-box/cbox.gltf");
    const light::VplSet vpls = test::monte_carlo_vpls(s, 48, 6, 3);
    for (const int k : {2, 3}) {
        SCOPED_TRACE(k);
        test::VplRenderSettings settings{.res = 64, .shadow_res = 256, .clamp = 0.05f};
        settings.interleave = k;
        const Image oracle = test::oracle_render(s, vpls, settings);
        const double error =
            compare_images(test::gpu_render(context(), s, vpls, settings), oracle).rel_mse;
        EXPECT_LT(error, 1.25 * 2.0 / 256.0);
        EXPECT_GT(oracle.mean().r, 0.0f);
        RecordProperty("relmse_k" + std::to_string(k), std::to_string(error));
    }
}

}  // namespace
}  // namespace mvpl::render
