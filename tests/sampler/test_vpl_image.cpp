// Whole images from the VPL oracle (slow): the estimator is unbiased with clamping off (Cornell
// box against Mitsuba 2, integrating sphere against its closed form), Halton primary samples beat
// random ones, One and All VPLs per path agree; and the throughput numbers.
//
// Tolerances come from the measured spread: every oracle image is the mean of B independent
// batches (different seeds), and the standard error of its mean is the batches' spread / √B.
#include <gtest/gtest.h>

#include <cstdio>

#include "engine/core/image_metrics.h"
#include "engine/light/light_sampler.h"
#include "engine/reference/path_tracer.h"
#include "engine/reference/vpl_gather.h"
#include "engine/sampler/monte_carlo_sampler.h"
#include "engine/scene/scene_loader.h"
#include "engine/trace/accel.h"
#include "tests/sampler/vpl_test_util.h"
#include "tests/support/scene_builder.h"

namespace mvpl {
namespace {

scene::Scene cornell_box() {
    return scene::load_scene(MVPL_ASSETS_DIR "/cornell-box/cbox.gltf");
}

// Max depth 6, clamping off: the image mean within 3% of Mitsuba's per channel, 8 batches of 128
// paths (≈ 3500 VPLs) at 128×128; the measured standard error of the mean is printed and must be
// below 1% for the 3% bound to mean something.
//
// One sample at each pixel centre is not Mitsuba's filtered pixel: the luminaire seen directly
// is half of the image mean and is only ~5 pixel rows tall at 128², so counting its coverage by
// centres is off by several percent. That term is deterministic and not what this test is about:
// it is swapped for the path tracer's box-filtered emission (max depth 1, 64 spp): mean − E_centres
// + E_box. (At identical receiver points the oracle's direct light equals next-event estimation
// to 0.01%; what is left is the aliasing of the other edges, ~1% at 64², less at 128².)
TEST(VplImage, CornellBoxIsUnbiased) {
    constexpr int kRes = 128;
    const scene::Scene s = cornell_box();
    const trace::Accel accel(s);
    const light::LightSampler lights(s);
    sampler::MonteCarloOptions o;
    o.paths = 128;
    o.seed = 1000;
    // At pixel centres, where emitted_centres below is taken (with jitter each batch would need
    // the emission at its own positions).
    const test::BatchedImage b = test::batched_oracle(s, o, 8, kRes, 6, /*jitter=*/false);
    reference::GatherOptions g;
    g.width = g.height = kRes;
    g.max_depth = 1;
    g.clamp = 0.0f;
    const Rgb emitted_centres = reference::gather_vpls(s, accel, {}, g).mean();
    reference::PathTracerOptions p;
    p.width = p.height = kRes;
    p.spp = 64;
    p.max_depth = 1;
    p.quiet = true;
    const Rgb emitted_box = reference::PathTracer(s, accel, lights).render(p).mean();
    const Rgb mean = b.mean.mean() - emitted_centres + emitted_box;
    const Rgb se = test::mean_standard_error(b);
    const Rgb mean_ref = read_exr(MVPL_ASSETS_DIR "/cornell-box/ref-cbox-d6-4096.exr").mean();
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(mean[c] / mean_ref[c], 1.0, 0.03) << "channel " << c;
        EXPECT_LT(se[c] / mean[c], 0.01) << "channel " << c;
        std::printf("cbox channel %d: oracle %.5f ± %.5f, Mitsuba %.5f (ratio %.4f)\n", c, mean[c],
                    se[c], mean_ref[c], mean[c] / mean_ref[c]);
    }
    RecordProperty("mean_ratio_red", std::to_string(mean.r / mean_ref.r));
}

// Point light in a closed Lambertian sphere, albedo a = 0.5, unlimited depth: every visible point
// has L = a·I/(πR²(1 − a)). Inside a sphere cos θ_j·cos θ'/d² = 1/(4R²) for every pair of points
// and nothing is occluded, so all pixels see the same sum and the only noise is in the paths'
// throughputs and lengths: the bound is 4 standard errors of the batch means plus 0.3% for the
// level-5 icosphere's facets (within 0.07% of R, and the shading normals differ from the facets').
TEST(VplImage, IntegratingSphere) {
    const float albedo = 0.5f, radius = 2.0f, intensity = 5.0f;
    const scene::Scene s = test::make_integrating_sphere(albedo, radius, intensity);
    sampler::MonteCarloOptions o;
    o.paths = 128;
    o.seed = 77;
    const test::BatchedImage b = test::batched_oracle(s, o, 8, 16, -1);
    const double expected = albedo * intensity / (kPi * radius * radius * (1.0 - albedo));
    const double mean = b.mean.mean().g, se = test::mean_standard_error(b).g;
    std::printf("sphere: oracle %.5f ± %.5f, analytic %.5f\n", mean, se, expected);
    EXPECT_NEAR(mean, expected, 4.0 * se + 3e-3 * expected);
}

double rmse(const Image& a, const Image& r) {
    return compare_images(a, r).rmse;
}

// Direct light from a square area light (max depth 2: one area VPL per path, 3 primary
// dimensions): Halton points stratify the light, so at 256 VPLs the error against a 16384-VPL
// random reference is lower than random sampling's, summed over four seeds.
TEST(VplImage, HaltonBeatsRandom) {
    const scene::Scene s = test::area_lit_plane();
    sampler::MonteCarloOptions o;
    o.paths = 16384;
    o.seed = 500;
    const Image reference = test::batched_oracle(s, o, 1, 32, 2).mean;
    double err_random = 0.0, err_halton = 0.0;
    o.paths = 256;
    for (uint64_t seed = 0; seed < 4; ++seed) {
        o.seed = seed;
        o.qmc = false;
        err_random += rmse(test::batched_oracle(s, o, 1, 32, 2).mean, reference);
        o.qmc = true;
        err_halton += rmse(test::batched_oracle(s, o, 1, 32, 2).mean, reference);
    }
    std::printf("rmse at 256 VPLs: random %.5f, halton %.5f\n", err_random / 4, err_halton / 4);
    EXPECT_LT(err_halton, err_random);
}

// One VPL per path (power × the path's VPL count) has the same expectation as All: the image
// means agree within 4 combined standard errors, in the Cornell box (max depth 6) and in the
// integrating sphere (unlimited depth, where the standard errors are small).
void expect_one_and_all_agree(const scene::Scene& s, int max_depth, int resolution) {
    sampler::MonteCarloOptions o;
    o.paths = 256;
    o.seed = 40;
    const test::BatchedImage all = test::batched_oracle(s, o, 8, resolution, max_depth);
    o.per_path = sampler::VplsPerPath::One;
    o.seed = 80;
    const test::BatchedImage one = test::batched_oracle(s, o, 8, resolution, max_depth);
    const Rgb m_all = all.mean.mean(), m_one = one.mean.mean();
    const Rgb se_all = test::mean_standard_error(all), se_one = test::mean_standard_error(one);
    for (int c = 0; c < 3; ++c) {
        const double se = std::sqrt(se_all[c] * se_all[c] + se_one[c] * se_one[c]);
        std::printf("channel %d: all %.5f ± %.5f, one %.5f ± %.5f\n", c, m_all[c], se_all[c],
                    m_one[c], se_one[c]);
        EXPECT_NEAR(m_one[c], m_all[c], 4.0 * se) << "channel " << c;
    }
}

TEST(VplImage, OneAndAllAgree) {
    expect_one_and_all_agree(cornell_box(), 6, 32);
    expect_one_and_all_agree(test::make_integrating_sphere(0.5f, 2.0f, 5.0f), -1, 8);
}

// Not a check: the numbers for the report (light tracer VPL/s, oracle seconds per 1000 VPLs at
// 128² on the Cornell box).
TEST(VplImage, Throughput) {
    const scene::Scene s = cornell_box();
    const trace::Accel accel(s);
    const light::LightSampler lights(s);
    const sampler::MonteCarloSampler mc(s, accel, lights);
    sampler::MonteCarloOptions o;
    o.paths = 50000;
    sampler::SamplerStats stats;
    const light::VplSet all = mc.generate(o, &stats);
    const std::vector<light::Vpl>& vpls = all.vpls;
    const double vpl_rate = double(stats.vpls) / stats.seconds;
    o.paths = 300;
    light::VplSet set = mc.generate(o);
    set.vpls.resize(std::min<size_t>(set.vpls.size(), 1000));
    const std::vector<light::Vpl>& subset = set.vpls;
    reference::GatherOptions g;
    g.width = g.height = 128;
    g.clamp = 0.0f;
    reference::GatherStats gs;
    reference::gather_vpls(s, accel, set, g, &gs);
    const double per_1000 = gs.seconds * 1000.0 / double(subset.size());
    std::printf("light tracer: %llu paths, %llu VPLs in %.3f s = %.0f VPL/s (%.2f Mrays/s)\n",
                (unsigned long long)stats.paths, (unsigned long long)stats.vpls, stats.seconds,
                vpl_rate, stats.rays / stats.seconds * 1e-6);
    std::printf("oracle: %zu VPLs at 128x128 in %.3f s = %.3f s per 1000 VPLs (%.2f Mrays/s)\n",
                subset.size(), gs.seconds, per_1000, gs.rays / gs.seconds * 1e-6);
    RecordProperty("vpl_per_second", std::to_string(vpl_rate));
    RecordProperty("oracle_seconds_per_1000_vpls_128", std::to_string(per_1000));
    EXPECT_GT(vpls.size(), 0u);
}

}  // namespace
}  // namespace mvpl
