#pragma once
// Row-column sampling's draws against the CPU oracle on the Cornell box, for the tests of the
// CPU's matrix (test_row_column.cpp) and the GPU's (test_row_column_gpu.cpp): a pool, its
// representatives' images, and the test that their mean over draws is the pool's image.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "engine/core/image.h"
#include "engine/light/light_sampler.h"
#include "engine/light/virtual_sphere.h"
#include "engine/manylights/row_column_sampler.h"
#include "engine/reference/vpl_gather.h"
#include "engine/sampler/monte_carlo_stream.h"
#include "engine/scene/scene_loader.h"
#include "engine/trace/accel.h"

namespace mvpl::manylights_test {

constexpr int kRes = 16;
constexpr int kBlock = 4;  // blocks of kBlock² pixels: (kRes / kBlock)² of them

struct Cornell {
    scene::Scene scene = scene::load_scene(MVPL_ASSETS_DIR "/cornell-box/cbox.gltf");
    trace::Accel accel{scene};
    light::LightSampler lights{scene};
};
inline const Cornell& cornell() {
    static const Cornell c;
    return c;
}

// The first `n` VPLs of a scene's Monte Carlo stream (all VPLs of each path).
inline std::vector<light::Vpl> stream_pool(const scene::Scene& scene, const trace::Accel& accel,
                                           const light::LightSampler& lights, size_t n,
                                           uint64_t seed) {
    sampler::MonteCarloOptions o;
    o.seed = seed;
    sampler::MonteCarloStream stream(scene, accel, lights, o);
    std::vector<light::Vpl> v;
    while (v.size() < n)
        stream.next(64, v);
    v.resize(n);
    return v;
}

// The first `n` VPLs of the Cornell box's stream.
inline std::vector<light::Vpl> pool_of(size_t n, uint64_t seed) {
    const Cornell& c = cornell();
    return stream_pool(c.scene, c.accel, c.lights, n, seed);
}

// reduce() cuts pools of `pool` VPLs.
// columns: the matrix's evaluator (null: the CPU's).
inline manylights::RowColumnSampler sampler_with(uint32_t rows, uint32_t clusters, uint64_t seed,
                                                 uint32_t pool = 4096,
                                                 manylights::ColumnEvaluator* columns = nullptr) {
    const Cornell& c = cornell();
    manylights::RowColumnContext context;
    context.scene = &c.scene;
    context.accel = &c.accel;
    context.camera = &c.scene.camera;
    context.rows.width = context.rows.height = kRes;
    context.clamp = light::kDefaultClamp;
    context.vsl_radius = light::kDefaultVslRadius;
    context.seed = seed;
    context.columns = columns;
    manylights::RowColumnOptions o;
    o.pool = pool;
    o.rows = rows;
    o.clusters = clusters;
    return manylights::RowColumnSampler(context, o);
}

inline Image oracle(const std::vector<light::Vpl>& vpls) {
    reference::GatherOptions g;
    g.width = g.height = kRes;
    g.max_depth = 0;            // VPL light only
    g.subpixel.jitter = false;  // every VPL at the pixel centres
    const Cornell& c = cornell();
    return reference::gather_vpls(c.scene, c.accel, {vpls, 1.0}, g);
}

// Mean luminance of each kBlock² block, then of the whole image.
inline std::vector<double> blocks(const Image& image) {
    const int n = kRes / kBlock;
    std::vector<double> b(size_t(n * n) + 1, 0.0);
    for (int y = 0; y < kRes; ++y) {
        for (int x = 0; x < kRes; ++x) {
            const double l = luminance(image.at(x, y));
            b[size_t((y / kBlock) * n + x / kBlock)] += l / double(kBlock * kBlock);
            b.back() += l / double(kRes * kRes);
        }
    }
    return b;
}

// Over `passes` draws (seeds 1 …), each block's mean of the representatives' image equals the
// pool's within 5 standard errors of that mean (P(|t| > 5) ≈ 10⁻⁶ a block at 100+ degrees of
// freedom), and the bound is not so loose that it would pass anything: the mean is the pool's
// within 10 % on the whole image.
inline void expect_unbiased(uint32_t rows, uint32_t clusters, int passes,
                            manylights::ColumnEvaluator* columns = nullptr) {
    const std::vector<light::Vpl> pool = pool_of(256, 7);
    const std::vector<double> full = blocks(oracle(pool));
    std::vector<std::vector<double>> draws;
    for (int p = 0; p < passes; ++p) {
        manylights::RowColumnSampler s =
            sampler_with(rows, clusters, 1 + uint64_t(p), 4096, columns);
        const std::vector<light::Vpl> reps = s.representatives(pool, 0, clusters);
        ASSERT_LE(reps.size(), size_t(clusters) + 1);
        draws.push_back(blocks(oracle(reps)));
    }
    for (size_t k = 0; k < full.size(); ++k) {
        double mean = 0.0, var = 0.0;
        for (const auto& d : draws)
            mean += d[k] / passes;
        for (const auto& d : draws)
            var += (d[k] - mean) * (d[k] - mean) / (passes - 1);
        const double se = std::sqrt(var / passes);
        EXPECT_NEAR(mean, full[k], 5.0 * se + 1e-6 * full[k]) << "block " << k;
        if (k + 1 == full.size()) {
            std::printf("R %u, C %u: whole image %.5f ± %.5f, pool %.5f\n", rows, clusters, mean,
                        se, full[k]);
            EXPECT_LT(se, 0.1 * full[k]);
        }
    }
}

}  // namespace mvpl::manylights_test
