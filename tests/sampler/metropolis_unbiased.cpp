// The Metropolis sampler's unbiasedness check (metropolis_unbiased.h): the mean of M independent
// Metropolis estimates of a small oracle image equals the Monte Carlo mean (same clamping, same
// gather) within a bound derived from the spread of both.
#include "tests/sampler/metropolis_unbiased.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "engine/light/light_sampler.h"
#include "engine/reference/vpl_gather.h"
#include "engine/sampler/metropolis_stream.h"
#include "engine/sampler/monte_carlo_stream.h"
#include "engine/scene/scene_loader.h"
#include "engine/trace/accel.h"
#include "tests/support/sample_statistics.h"

namespace mvpl::test {

// Regions: the whole image and its four quadrants (luminance_regions), which check that the VPLs
// the finite point set misses are still weighted right (the defensive term), not just the total.
void expect_metropolis_matches_monte_carlo(cluster::Cluster& ranks) {
    expect_metropolis_matches_monte_carlo(ranks, UnbiasedCheck{});
}

void expect_metropolis_matches_monte_carlo(cluster::Cluster& ranks, const UnbiasedCheck& check) {
    const scene::Scene scene = scene::load_scene(MVPL_ASSETS_DIR "/cornell-box/cbox.gltf");
    const trace::Accel accel(scene);
    const light::LightSampler lights(scene);
    const int runs = check.runs;
    constexpr int kRes = 16;
    constexpr uint64_t kWork = 256;
    reference::GatherOptions g;
    g.width = g.height = kRes;
    g.clamp = 0.05f;
    g.max_depth = 0;  // no emitted radiance: VPL light only
    // Pixel centres: the sub-pixel schedule follows a VPL's index in the whole set, which a rank's
    // share does not start at; the sampler's bias does not depend on the pixel filter.
    g.subpixel.jitter = false;
    // This rank's VPLs' part of the image (all of them on one process): the regions are linear in
    // it, so their sum over the ranks is the whole set's.
    auto estimate = [&](sampler::VplStream& s, bool shared, uint64_t work) {
        std::vector<light::Vpl> v;
        s.next(work, v);
        std::vector<double> r =
            luminance_regions(reference::gather_vpls(scene, accel, {std::move(v), s.scale()}, g));
        if (shared) ranks.sum_all(r);
        return r;
    };
    std::vector<std::vector<double>> mc, metro;
    for (int r = 0; r < runs; ++r) {
        sampler::MonteCarloOptions o;
        o.seed = 1000 + uint64_t(r);
        sampler::MonteCarloStream s(scene, accel, lights, o);
        mc.push_back(estimate(s, false, kWork));
        sampler::MetropolisOptions mo;
        mo.seed = 2000 + uint64_t(r);
        mo.chains = check.chains;
        mo.stratified_starts = check.stratified_starts;
        mo.bootstrap = 512;
        mo.importance.points = 16;  // few points: most pixels rely on the defensive term
        mo.importance.width = mo.importance.height = kRes;
        mo.importance.clamp = g.clamp;
        mo.cluster = &ranks;
        sampler::MetropolisStream m(scene, accel, lights, scene.camera, mo);
        metro.push_back(estimate(m, ranks.size() > 1, check.steps));
    }
    // Per region: |mean_m − mean_mc| ≤ 5·√(s²_m/M + s²_mc/M), s² the sample variances of the
    // M independent runs (Student t, ≈ 94 degrees of freedom: P(|t| > 5) ≈ 3·10⁻⁶ per region).
    for (size_t k = 0; k < 5; ++k) {
        double m1 = 0.0, m2 = 0.0;
        for (int r = 0; r < runs; ++r) {
            m1 += mc[r][k] / runs;
            m2 += metro[r][k] / runs;
        }
        double v1 = 0.0, v2 = 0.0;
        for (int r = 0; r < runs; ++r) {
            v1 += (mc[r][k] - m1) * (mc[r][k] - m1) / (runs - 1);
            v2 += (metro[r][k] - m2) * (metro[r][k] - m2) / (runs - 1);
        }
        ASSERT_GT(m1, 0.0);
        EXPECT_NEAR(m2, m1, 5.0 * std::sqrt(v1 / runs + v2 / runs)) << "region " << k;
        if (ranks.root())
            std::printf("region %zu: mc %.5f ± %.5f, metropolis %.5f ± %.5f\n", k, m1,
                        std::sqrt(v1 / runs), m2, std::sqrt(v2 / runs));
    }
}

}  // namespace mvpl::test
