// Direct light through the VPL oracle at max depth 2.
//
// Punctual lights: one light path gives the light's own VPL (power I for N = 1), and the oracle's
// pixel-centre value must equal the analytic L = ρ/π · I·falloff·cos θ / d² (or ρ/π · E·cos θ)
// at the point the centre ray hits: nothing is random, so the tolerance is float rounding (1e-4).
//
// Area light: the oracle averaged over B = 16 independent batches of area VPLs against the path
// tracer at max depth 2. Each 4×4 block of the two images is compared with the z-score
// |o − p| / √(se_o² + se_p² + (0.5% p)²): se_o from the spread of the batches, se_p from two path
// tracer seeds (pooled over the blocks in relative terms: one pair per block would be too noisy),
// and 0.5% for the box filter of the path tracer against pixel centres (the quadrature error of a
// smooth field). The 64 blocks must all lie within 5 (t with 15 degrees of freedom: P(|t| > 5)
// ≈ 2·10⁻⁴ per block).
#include <gtest/gtest.h>

#include "engine/core/image_metrics.h"
#include "engine/light/light_sampler.h"
#include "engine/reference/path_tracer.h"
#include "engine/reference/vpl_gather.h"
#include "engine/sampler/monte_carlo_sampler.h"
#include "engine/scene/camera.h"
#include "engine/trace/accel.h"
#include "tests/sampler/vpl_test_util.h"
#include "tests/support/lit_plane.h"
#include "tests/support/scene_builder.h"

namespace mvpl {
namespace {

constexpr int kRes = 24;

void expect_oracle_matches_analytic(const scene::Scene& s) {
    const trace::Accel accel(s);
    const light::LightSampler lights(s);
    sampler::MonteCarloOptions o;
    o.paths = 1;
    o.tracer.max_depth = 2;
    const light::VplSet set = sampler::MonteCarloSampler(s, accel, lights).generate(o);
    const std::vector<light::Vpl>& vpls = set.vpls;
    ASSERT_EQ(vpls.size(), 1u);
    reference::GatherOptions g;
    g.width = g.height = kRes;
    g.max_depth = 2;
    g.clamp = 0.0f;
    const Image image = reference::gather_vpls(s, accel, set, g);
    double lit = 0.0;
    for (int y = 0; y < kRes; ++y) {
        for (int x = 0; x < kRes; ++x) {
            const scene::CameraRay r =
                scene::generate_camera_ray(s.camera, kRes, kRes, Vec2(x + 0.5f, y + 0.5f));
            const float t = -r.origin.y / r.direction.y;
            const Rgb expected = test::lit_plane_radiance(s.lights[0], r.origin + t * r.direction);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(image.at(x, y)[c], expected[c], 1e-4f * expected[c] + 1e-7f)
                    << "pixel " << x << "," << y << " channel " << c;
            lit += expected.g;
        }
    }
    EXPECT_GT(lit, 0.0);
}

TEST(OracleDirect, PointLight) {
    expect_oracle_matches_analytic(test::make_lit_plane(test::example_point_light()));
}

TEST(OracleDirect, SpotLight) {
    expect_oracle_matches_analytic(test::make_lit_plane(test::example_spot_light()));
}

TEST(OracleDirect, DirectionalLight) {
    expect_oracle_matches_analytic(test::make_lit_plane(test::example_directional_light()));
}

// Clamping: d_min = clamp · bounding-box diagonal replaces d² by max(d², d_min²). A point light
// 0.05 above the plane with d_min = 0.25 (clamp 0.25 over the 4×4 plane's diagonal √32): every
// pixel closer than d_min sees ρ/π · I·cos θ / d_min², the others the unclamped value.
TEST(OracleDirect, ClampingBoundsTheDistance) {
    scene::Light l;
    l.type = scene::LightType::Point;
    l.position = Vec3(0.3f, 0.05f, 0.0f);
    l.intensity = Rgb(1.0f);
    const scene::Scene s = test::make_lit_plane(l);
    const trace::Accel accel(s);
    const light::LightSampler lights(s);
    sampler::MonteCarloOptions o;
    o.paths = 1;
    o.tracer.max_depth = 2;
    const auto vpls = sampler::MonteCarloSampler(s, accel, lights).generate(o);
    const float d_min = 0.25f;
    reference::GatherOptions g;
    g.width = g.height = kRes;
    g.max_depth = 2;
    g.clamp = d_min / s.bounds().diagonal();
    const Image image = reference::gather_vpls(s, accel, vpls, g);
    int clamped = 0;
    for (int y = 0; y < kRes; ++y) {
        for (int x = 0; x < kRes; ++x) {
            const scene::CameraRay r =
                scene::generate_camera_ray(s.camera, kRes, kRes, Vec2(x + 0.5f, y + 0.5f));
            const Vec3 p = r.origin + (-r.origin.y / r.direction.y) * r.direction;
            const Vec3 d = l.position - p;
            const float dist2 = glm::dot(d, d);
            const float expected = test::kLitPlaneAlbedo * kInvPi * d.y / std::sqrt(dist2) /
                                   std::max(dist2, d_min * d_min);
            clamped += dist2 < d_min * d_min;
            EXPECT_NEAR(image.at(x, y).g, expected, 1e-4f * expected + 1e-7f) << x << "," << y;
        }
    }
    EXPECT_GT(clamped, 0);
}

TEST(OracleDirect, AreaLightConvergesToThePathTracer) {
    constexpr int kRes32 = 32, kBlock = 4, kBatches = 16;
    const scene::Scene s = test::area_lit_plane();
    sampler::MonteCarloOptions o;
    o.paths = 256;
    o.seed = 100;
    const test::BatchedImage oracle = test::batched_oracle(s, o, kBatches, kRes32, 2);

    const trace::Accel accel(s);
    const light::LightSampler lights(s);
    const reference::PathTracer tracer(s, accel, lights);
    reference::PathTracerOptions p;
    p.width = p.height = kRes32;
    p.spp = 256;
    p.max_depth = 2;
    p.quiet = true;
    p.seed = 1;
    const Image pt1 = block_average(tracer.render(p), kBlock);
    p.seed = 2;
    const Image pt2 = block_average(tracer.render(p), kBlock);

    // Standard error of a block of the oracle: the batches' block values' spread / √B.
    std::vector<Image> batch_blocks;
    for (const Image& b : oracle.batches)
        batch_blocks.push_back(block_average(b, kBlock));
    const Image ob = block_average(oracle.mean, kBlock);
    // Pooled relative variance of the mean of the two path tracer renders: E[(p1 − p2)²] = 2σ²,
    // and the mean of two has σ²/2.
    double rel_var_pt = 0.0;
    int lit_blocks = 0;
    for (size_t i = 0; i < pt1.pixels().size(); ++i) {
        const double m = 0.5 * (pt1.pixels()[i].g + pt2.pixels()[i].g);
        if (!(m > 0.0)) continue;
        const double d = pt1.pixels()[i].g - pt2.pixels()[i].g;
        rel_var_pt += 0.25 * d * d / (m * m);
        ++lit_blocks;
    }
    ASSERT_GT(lit_blocks, 32);
    rel_var_pt /= lit_blocks;
    double worst = 0.0;
    for (size_t i = 0; i < ob.pixels().size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            const double pm = 0.5 * (pt1.pixels()[i][c] + pt2.pixels()[i][c]);
            double s1 = 0.0, s2 = 0.0;
            for (const Image& b : batch_blocks) {
                s1 += b.pixels()[i][c];
                s2 += double(b.pixels()[i][c]) * b.pixels()[i][c];
            }
            const double mean = s1 / kBatches;
            const double var_o = std::max(0.0, (s2 - kBatches * mean * mean) / (kBatches - 1));
            const double se2 =
                var_o / kBatches + rel_var_pt * pm * pm + (5e-3 * pm) * (5e-3 * pm) + 1e-12;
            const double z = std::abs(ob.pixels()[i][c] - pm) / std::sqrt(se2);
            worst = std::max(worst, z);
            EXPECT_LT(z, 5.0) << "block " << i << " channel " << c << ": oracle "
                              << ob.pixels()[i][c] << " path tracer " << pm;
        }
    }
    RecordProperty("worst_z", std::to_string(worst));
    std::printf("area light: worst block z-score %.2f, path tracer relative sd %.4f\n", worst,
                std::sqrt(rel_var_pt));
}

}  // namespace
}  // namespace mvpl
