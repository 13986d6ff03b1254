// Unbiasedness of the Metropolis VPL sampler on the Cornell box: the mean of M independent
// Metropolis estimates of a small oracle image equals the Monte Carlo mean (same clamping, same
// gather) within a bound derived from the spread of both.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/light/light_sampler.h"
#include "engine/reference/vpl_gather.h"
#include "engine/scene/scene_loader.h"
#include "engine/trace/accel.h"
#include "sampler/metropolis_stream.h"
#include "sampler/monte_carlo_stream.h"
#include "tests/support/sample_statistics.h"

namespace mvpl {
namespace {

// The whole image and its four quadrants: the quadrants check that the VPLs the finite point set
// misses are still weighted right (the defensive term), not just the total.
using test::luminance_regions;

TEST(MetropolisUnbiased, CornellBoxMatchesMonteCarlo) {
    const scene::Scene scene = scene::load_scene(MVPL_ASSETS_DIR "/cornell-box/cbox.gltf");
    const trace::Accel accel(scene);
    const light::LightSampler lights(scene);
    constexpr int kRuns = 48, kRes = 16;
    constexpr uint64_t kWork = 256;
    reference::GatherOptions g;
    g.width = g.height = kRes;
    g.clamp = 0.05f;
    g.max_depth = 0;  // no emitted radiance: VPL light only
    auto estimate = [&](sampler::VplStream& s) {
        std::vector<light::Vpl> v;
        s.next(kWork, v);
        return luminance_regions(
            reference::gather_vpls(scene, accel, {std::move(v), s.scale()}, g));
    };
    std::vector<std::vector<double>> mc, metro;
    for (int r = 0; r < kRuns; ++r) {
        sampler::MonteCarloOptions o;
        o.seed = 1000 + uint64_t(r);
        sampler::MonteCarloStream s(scene, accel, lights, o);
        mc.push_back(estimate(s));
        sampler::MetropolisOptions mo;
        mo.seed = 2000 + uint64_t(r);
        mo.chains = 4;
        mo.bootstrap = 512;
        mo.importance.points = 16;  // few points: most pixels rely on the defensive term
        mo.importance.width = mo.importance.height = kRes;
        mo.importance.clamp = g.clamp;
        sampler::MetropolisStream m(scene, accel, lights, scene.camera, mo);
        metro.push_back(estimate(m));
    }
    // Per region: |mean_m − mean_mc| ≤ 5·√(s²_m/M + s²_mc/M), s² the sample variances of the
    // M independent runs (Student t, ≈ 94 degrees of freedom: P(|t| > 5) ≈ 3·10⁻⁶ per region).
    for (size_t k = 0; k < 5; ++k) {
        double m1 = 0.0, m2 = 0.0;
        for (int r = 0; r < kRuns; ++r) {
            m1 += mc[r][k] / kRuns;
            m2 += metro[r][k] / kRuns;
        }
        double v1 = 0.0, v2 = 0.0;
        for (int r = 0; r < kRuns; ++r) {
            v1 += (mc[r][k] - m1) * (mc[r][k] - m1) / (kRuns - 1);
            v2 += (metro[r][k] - m2) * (metro[r][k] - m2) / (kRuns - 1);
        }
        ASSERT_GT(m1, 0.0);
        EXPECT_NEAR(m2, m1, 5.0 * std::sqrt(v1 / kRuns + v2 / kRuns)) << "region " << k;
        std::printf("region %zu: mc %.5f ± %.5f, metropolis %.5f ± %.5f\n", k, m1,
                    std::sqrt(v1 / kRuns), m2, std::sqrt(v2 / kRuns));
    }
}

}  // namespace
}  // namespace mvpl
