// Sub-pixel sampling (issue 13, item 1): a half-plane edge across a pixel at a known coverage.
// The plane z = −1 faces the camera, is emissive and lit by a directional VPL, so its radiance R
// is the same everywhere; a pixel that the plane covers by a fraction c must read c · R once
// enough batches were shaded at their own sub-pixel positions, on the GPU and in the CPU oracle,
// and the two must agree pixel by pixel.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "engine/core/image.h"
#include "engine/core/subpixel.h"
#include "engine/reference/vpl_gather.h"
#include "engine/render/vpl_renderer.h"
#include "engine/scene/camera.h"
#include "engine/trace/accel.h"
#include "tests/gpu/gpu_test.h"
#include "tests/support/scene_builder.h"

namespace mvpl::render {
namespace {

using AntialiasingTest = gpu::testing::GpuTest;

constexpr int kSize = 8;
// The edge, in film coordinates: the plane covers (fx − 3) + (fy − 3) / 2 ≥ 0.8, so pixel (3, 3)
// is covered by ∫₀¹ (1 − 0.8 + v/2) dv = 0.45, and so is (2, 5), one column left two rows down.
constexpr float kEdge = 0.8f;
constexpr double kCoverage = 0.45;
const int kEdgePixels[][2] = {{3, 3}, {2, 5}, {4, 1}};
const Rgb kEmission(0.2f, 0.4f, 0.6f);
const Rgb kAlbedo(0.5f);

bool inside(float fx, float fy) {
    return (fx - 3.0f) + 0.5f * (fy - 3.0f) >= kEdge;
}

struct EdgeScene {
    scene::Scene scene;
    light::Vpl sun;
    Rgb radiance{0.0f};  // R: emission + the directional VPL's ρ/π · E, everywhere on the plane

    EdgeScene() {
        scene.camera = test::look_at(Vec3(0.0f), Vec3(0.0f, 0.0f, -1.0f), 0.8f);
        scene.has_camera = true;
        scene::Material m = test::diffuse_material(kAlbedo);
        m.emissive = kEmission;
        scene.materials = {m};
        // The film → plane map is affine: the edge's ends 20 rows above and below, and the
        // parallelogram extends 40 pixels to the right of it (its front face towards +z).
        const auto on_plane = [&](float fx, float fy) {
            const scene::CameraRay r =
                scene::generate_camera_ray(scene.camera, kSize, kSize, Vec2(fx, fy));
            return r.origin + r.direction * (-1.0f / r.direction.z);
        };
        const Vec3 top = on_plane(3.0f + kEdge + 10.0f, 3.0f - 20.0f);
        const Vec3 bottom = on_plane(3.0f + kEdge - 10.0f, 3.0f + 20.0f);
        const Vec3 right = on_plane(40.0f, 0.0f) - on_plane(0.0f, 0.0f);
        scene.meshes.push_back(test::make_quad(top, bottom - top, right, 0));
        sun.type = light::VplType::Directional;
        sun.normal = glm::normalize(Vec3(0.3f, -0.2f, -1.0f));  // direction of travel
        sun.power = Rgb(2.0f, 1.5f, 1.0f);
        radiance = kEmission + kAlbedo * kInvPi * sun.power * (-sun.normal.z);
    }

    // n copies of the VPL, each power·scale = power / n: the sum is one sun whatever n.
    light::VplSet vpls(size_t n, float power_scale = 1.0f) const {
        light::Vpl v = sun;
        v.power *= power_scale;
        return {std::vector<light::Vpl>(n, v), 1.0 / double(n)};
    }

    Image gpu(gpu::Context& context, const light::VplSet& set, uint32_t batch, bool jitter) const {
        VplRenderer renderer(context, scene);
        RenderOptions o;
        o.width = o.height = kSize;
        o.shadow_resolution = 16;
        o.batch = batch;
        o.clamp = 0.0f;
        o.jitter = jitter;
        return renderer.render(set, o);
    }

    Image oracle(const light::VplSet& set, uint32_t batch, bool jitter) const {
        const trace::Accel accel(scene);
        reference::GatherOptions o;
        o.width = o.height = kSize;
        o.clamp = 0.0f;
        o.subpixel = {jitter, batch};
        return reference::gather_vpls(scene, accel, set, o);
    }
};

double relative_to(const Rgb& got, const Rgb& want) {
    double worst = 0.0;
    for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(double(got[c]) - double(want[c])) / double(want[c]));
    return worst;
}

// The rasteriser snaps vertices to a fixed-point sub-pixel grid, so a position that close to the
// edge may fall on the other side than the oracle's exact ray: each such position moves a pixel
// by R / positions (measured on lavapipe: one position of 256, 0.0039 R).
void expect_gpu_matches_oracle(const Image& gpu, const Image& oracle, const Rgb& radiance,
                               double allowed) {
    double worst = 0.0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            for (int c = 0; c < 3; ++c) {
                const double d = std::abs(double(gpu.at(x, y)[c]) - double(oracle.at(x, y)[c]));
                worst = std::max(worst, d / double(radiance[c]));
            }
        }
    }
    EXPECT_LE(worst, allowed);
    std::printf("GPU vs oracle: worst pixel difference %.5f R\n", worst);
}

TEST_F(AntialiasingTest, AnEdgePixelConvergesToItsCoverageTimesTheRadiance) {
    const EdgeScene s;
    constexpr size_t kPositions = 256;  // batch 1: one position per VPL
    const light::VplSet set = s.vpls(kPositions);
    const Image gpu = s.gpu(context(), set, 1, true);
    const Image oracle = s.oracle(set, 1, true);
    for (const Image* image : {&gpu, &oracle}) {
        const char* name = image == &gpu ? "GPU" : "oracle";
        // Whole pixels on either side are exact.
        EXPECT_LT(relative_to(image->at(6, 3), s.radiance), 1e-4) << name;
        EXPECT_EQ(image->at(0, 3), Rgb(0.0f)) << name;
        for (const auto& p : kEdgePixels) {
            const Rgb want = s.radiance * float(kCoverage);
            const double error = relative_to(image->at(p[0], p[1]), want);
            EXPECT_LT(error, 0.02) << name << " pixel " << p[0] << "," << p[1];
            std::printf("%s pixel %d,%d: %.4f of R (coverage %.2f)\n", name, p[0], p[1],
                        image->at(p[0], p[1]).r / s.radiance.r, kCoverage);
        }
    }
    expect_gpu_matches_oracle(gpu, oracle, s.radiance, 2.0 / kPositions);
}

// Without jitter every batch samples the pixel centre, which lies outside the plane at (3, 3):
// the pixel reads 0 however many VPLs, 100 % off its coverage. (What the test above guards.)
TEST_F(AntialiasingTest, WithoutJitterTheEdgePixelIsItsCentreSample) {
    const EdgeScene s;
    ASSERT_FALSE(inside(3.5f, 3.5f));
    const light::VplSet set = s.vpls(64);
    for (const Image& image : {s.gpu(context(), set, 1, false), s.oracle(set, 1, false)})
        EXPECT_EQ(image.at(3, 3), Rgb(0.0f));
}

// A VPL count that is no multiple of the batch: 255 VPLs in batches of 4 are 64 positions, the
// last with 3 VPLs. With the VPLs' power zeroed the image is the emission averaged over the 64
// positions, exactly the fraction of them inside the plane; with power, GPU and oracle agree.
TEST_F(AntialiasingTest, EmissionIsAveragedOverThePositionsWhenTheLastBatchIsPartial) {
    const EdgeScene s;
    constexpr uint32_t kBatch = 4;
    const SubpixelSchedule schedule{true, kBatch};
    ASSERT_EQ(schedule.positions_after(255), 64u);
    const Image dark = s.gpu(context(), s.vpls(255, 0.0f), kBatch, true);
    for (const auto& p : kEdgePixels) {
        int hits = 0;
        for (uint64_t i = 0; i < 64; ++i) {
            const Vec2 at = schedule.position(i);
            hits += inside(float(p[0]) + at.x, float(p[1]) + at.y);
        }
        const Rgb want = kEmission * (float(hits) / 64.0f);
        // Off by at most one position (the snapping above): E / 64.
        EXPECT_LT(relative_to(dark.at(p[0], p[1]) - want + kEmission, kEmission), 1.5 / 64.0)
            << "pixel " << p[0] << "," << p[1] << " " << hits << " of 64 inside";
    }
    const light::VplSet set = s.vpls(255);
    expect_gpu_matches_oracle(s.gpu(context(), set, kBatch, true), s.oracle(set, kBatch, true),
                              s.radiance, 2.0 / 64.0);
}

}  // namespace
}  // namespace mvpl::render
