// The whole chain — emission sampling, light tracing, VPL records, gather — against the path
// tracer at max depth 4 (direct light and two bounces) for every light type, at the same receiver
// points: the path tracer is evaluated on the pixel-centre rays the oracle uses (not its
// box-filtered render), so pixel sampling cannot hide or fake a difference.
//
// Scene: a Lambertian floor and, above it, a one-sided panel facing down; the camera sees the
// floor. The floor receives the light directly, from the panel where the light reaches it (one
// bounce), and from the panel that the floor lit (two bounces: the only indirect light of the
// spot light, which points down);
// panel and floor are a unit apart, so no VPL is near a receiver (no 1/d² spikes: the batch
// spread is an honest error estimate). Each of the 16 blocks of 4×4 pixels and each channel is
// compared with z = |o − p| / √(se_o² + se_p²), se_o from 16 independent VPL batches and se_p
// from the path tracer's per-sample spread; all must stay below 5 (t with 15 degrees of freedom:
// P(|t| > 5) ≈ 2·10⁻⁴ per comparison).
#include <gtest/gtest.h>

#include "engine/core/image_metrics.h"
#include "engine/light/light_sampler.h"
#include "engine/reference/path_tracer.h"
#include "engine/scene/camera.h"
#include "engine/trace/accel.h"
#include "tests/sampler/vpl_test_util.h"
#include "tests/support/scene_builder.h"

namespace mvpl {
namespace {

constexpr int kOracleRes = 16, kBlock = 4, kBatches = 16, kSpp = 2048, kDepth = 4;

scene::Scene floor_and_panel() {
    scene::Scene s;
    s.materials.push_back(test::diffuse_material(Rgb(0.7f, 0.5f, 0.3f)));
    s.materials.push_back(test::diffuse_material(Rgb(0.8f)));
    s.meshes.push_back(test::make_quad(Vec3(-2, 0, -2), Vec3(0, 0, 4), Vec3(4, 0, 0), 0));
    // cross((1,0,0), (0,0,1)) = (0,−1,0): facing down.
    s.meshes.push_back(test::make_quad(Vec3(-1.5f, 1.0f, -1.5f), Vec3(2, 0, 0), Vec3(0, 0, 3), 1));
    s.camera = test::look_at(Vec3(0.2f, 0.6f, 2.0f), Vec3(0.2f, 0.0f, 0.0f), 0.8f);
    s.has_camera = true;
    return s;
}

void expect_oracle_matches_path_tracer(const scene::Scene& s) {
    sampler::MonteCarloOptions o;
    o.paths = 256;
    o.seed = 7;
    // At the pixel centres, where the path tracer below is evaluated (no sub-pixel jitter).
    const test::BatchedImage oracle =
        test::batched_oracle(s, o, kBatches, kOracleRes, kDepth, /*jitter=*/false);

    const trace::Accel accel(s);
    const light::LightSampler lights(s);
    const reference::PathTracer tracer(s, accel, lights);
    // Per block: the sum and the sum of squares of the per-sample block contributions.
    constexpr int kBlocks = kOracleRes / kBlock;
    std::vector<DVec3> sum(kBlocks * kBlocks, DVec3(0.0)), sum2(kBlocks * kBlocks, DVec3(0.0));
    for (int y = 0; y < kOracleRes; ++y) {
        for (int x = 0; x < kOracleRes; ++x) {
            const scene::CameraRay cr = scene::generate_camera_ray(s.camera, kOracleRes, kOracleRes,
                                                                   Vec2(x + 0.5f, y + 0.5f));
            Rng rng(11, uint64_t(y * kOracleRes + x));
            const int b = (y / kBlock) * kBlocks + x / kBlock;
            for (int i = 0; i < kSpp; ++i) {
                const DVec3 L(tracer.radiance(trace::Ray{cr.origin, cr.direction}, rng, kDepth, 5));
                sum[b] += L;
                sum2[b] += L * L;
            }
        }
    }
    std::vector<Image> batch_blocks;
    for (const Image& im : oracle.batches)
        batch_blocks.push_back(block_average(im, kBlock));
    const Image ob = block_average(oracle.mean, kBlock);
    const double n_pt = double(kSpp) * kBlock * kBlock;  // samples per block
    double worst = 0.0, lit = 0.0;
    for (int b = 0; b < kBlocks * kBlocks; ++b) {
        for (int c = 0; c < 3; ++c) {
            // Pixels of a block are not identically distributed, but the block mean's variance
            // is still bounded by the pooled per-sample variance / n (it adds the spread of the
            // pixel means, so this errs on the safe side).
            const double pt = sum[b][c] / n_pt;
            const double var_pt = std::max(0.0, sum2[b][c] / n_pt - pt * pt) / n_pt;
            double s1 = 0.0, s2 = 0.0;
            for (const Image& im : batch_blocks) {
                s1 += im.pixels()[b][c];
                s2 += double(im.pixels()[b][c]) * im.pixels()[b][c];
            }
            const double m = s1 / kBatches;
            const double var_o = std::max(0.0, (s2 - kBatches * m * m) / (kBatches - 1)) / kBatches;
            const double z = std::abs(ob.pixels()[b][c] - pt) / std::sqrt(var_o + var_pt + 1e-14);
            worst = std::max(worst, z);
            lit += pt;
            EXPECT_LT(z, 5.0) << "block " << b << " channel " << c << ": oracle "
                              << ob.pixels()[b][c] << " path tracer " << pt;
        }
    }
    EXPECT_GT(lit, 0.0);
    std::printf("worst z %.2f, image mean oracle %.5f\n", worst, oracle.mean.mean().g);
}

TEST(OracleVsPathTracer, PointLight) {
    scene::Scene s = floor_and_panel();
    scene::Light l;
    l.type = scene::LightType::Point;
    l.position = Vec3(0.3f, 0.5f, -0.2f);
    l.intensity = Rgb(2.0f);
    s.lights.push_back(l);
    expect_oracle_matches_path_tracer(s);
}

TEST(OracleVsPathTracer, SpotLight) {
    scene::Scene s = floor_and_panel();
    scene::Light l;
    l.type = scene::LightType::Spot;
    l.position = Vec3(0.0f, 0.6f, 0.0f);
    l.direction = glm::normalize(Vec3(0.3f, -1.0f, 0.2f));
    l.inner_cone = 0.4f;
    l.outer_cone = 0.9f;
    l.intensity = Rgb(3.0f);
    s.lights.push_back(l);
    expect_oracle_matches_path_tracer(s);
}

TEST(OracleVsPathTracer, DirectionalLight) {
    scene::Scene s = floor_and_panel();
    scene::Light l;
    l.type = scene::LightType::Directional;
    // From the +x side, under the panel's edge at x = 0.5.
    l.direction = glm::normalize(Vec3(-1.0f, -0.6f, 0.1f));
    l.intensity = Rgb(1.5f);
    s.lights.push_back(l);
    expect_oracle_matches_path_tracer(s);
}

TEST(OracleVsPathTracer, AreaLight) {
    scene::Scene s = floor_and_panel();
    scene::Material emitter = test::diffuse_material(Rgb(0.0f));
    emitter.emissive = Rgb(3.0f, 2.0f, 1.0f);
    s.materials.push_back(emitter);
    s.meshes.push_back(
        test::make_quad(Vec3(0.6f, 0.7f, -0.5f), Vec3(0.4f, 0, 0), Vec3(0, 0, 0.4f), 2));
    expect_oracle_matches_path_tracer(s);
}

}  // namespace
}  // namespace mvpl
