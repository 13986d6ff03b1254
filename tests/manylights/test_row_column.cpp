// Matrix row-column sampling (engine/manylights) against the CPU oracle: the representatives'
// image is the pool's in expectation (per block, within a bound from the passes' own spread),
// every VPL with power keeps a probability above 0, the same seed gives the same clusters, and
// with a cluster per VPL the image is the pool's to the bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "engine/integrator/vpl_integrator.h"
#include "engine/light/light_sampler.h"
#include "engine/manylights/column_clustering.h"
#include "engine/manylights/reduced_matrix.h"
#include "engine/manylights/representatives.h"
#include "engine/manylights/row_column_sampler.h"
#include "engine/reference/vpl_gather.h"
#include "engine/sampler/monte_carlo_stream.h"
#include "engine/scene/camera.h"
#include "engine/scene/scene_loader.h"
#include "engine/trace/accel.h"
#include "tests/manylights/unbiased_draws.h"

namespace mvpl {
namespace {

using namespace manylights_test;

// The CPU matrix's sketches of `pool` on `rows` rows of the Cornell box's kRes² image (d_min 0.1),
// the rows and the sketch drawn from `seed`.
manylights::ColumnSketches cornell_sketches(const std::vector<light::Vpl>& pool, int rows,
                                            uint64_t seed) {
    const Cornell& c = cornell();
    const std::vector<manylights::Row> r =
        manylights::make_rows(c.scene, c.accel, c.scene.camera, {kRes, kRes, rows, {}}, seed, 0);
    const manylights::MatrixContext mc{&c.accel, r, 0.01f, 0.0f};
    return manylights::sketch_columns(mc, pool, 16, seed);
}

TEST(RowColumn, UnbiasedOverDraws) {
    expect_unbiased(32, 32, 160);
}

// Two rows see few VPLs: most columns have norm 0 and are drawn by power alone; the pixels no
// row sees keep their expectation.
TEST(RowColumn, UnbiasedWithRowsThatMissMostLight) {
    expect_unbiased(2, 16, 160);
}

TEST(RowColumn, EveryVplWithPowerCanBeDrawn) {
    const Cornell& c = cornell();
    const std::vector<light::Vpl> pool = pool_of(256, 3);
    for (uint32_t rows : {1u, 2u, 32u}) {
        const std::vector<manylights::Row> r = manylights::make_rows(
            c.scene, c.accel, c.scene.camera, {kRes, kRes, int(rows), {}}, 5, 0);
        const float d_min = light::kDefaultClamp * c.scene.bounds().diagonal();
        const manylights::MatrixContext mc{&c.accel, r, d_min * d_min, 0.0f};
        const manylights::ColumnSketches s = manylights::sketch_columns(mc, pool, 16, 9);
        const auto clusters = manylights::cluster_columns(s, 16, 9);
        size_t columns = 0, unseen = 0;
        for (const manylights::Cluster& k : clusters) {
            double sum = 0.0;
            for (size_t i = 0; i < k.columns.size(); ++i) {
                const double p = manylights::selection_probability(k, i, s.norms, pool, 0.1f);
                EXPECT_GT(p, 0.0) << "column " << k.columns[i];
                sum += p;
                unseen += s.norms[k.columns[i]] > 0.0f ? 0 : 1;
            }
            EXPECT_NEAR(sum, 1.0, 1e-9);
            columns += k.columns.size();
        }
        EXPECT_EQ(columns, pool.size());  // a partition
        EXPECT_LE(clusters.size(), 17u);
        if (rows <= 2) {
            EXPECT_GT(unseen, 0u) << "the case of columns no row sees";
        }
    }
}

bool same_vpls(const std::vector<light::Vpl>& a, const std::vector<light::Vpl>& b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i) {
        if (a[i].position != b[i].position || a[i].power != b[i].power) return false;
    }
    return true;
}

TEST(RowColumn, SameSeedSameClustersAndRepresentatives) {
    const std::vector<light::Vpl> pool = pool_of(512, 11);
    auto draw = [&](uint64_t seed) {
        manylights::RowColumnSampler s = sampler_with(32, 40, seed);
        std::vector<light::Vpl> v = pool;
        s.reduce(v);  // a pool of the default size: all 512 at once
        return v;
    };
    const std::vector<light::Vpl> a = draw(4), b = draw(4), c = draw(5);
    EXPECT_TRUE(same_vpls(a, b));
    EXPECT_FALSE(same_vpls(a, c));
    // The clusters themselves, from the same sketches.
    const Cornell& k = cornell();
    const std::vector<manylights::Row> r =
        manylights::make_rows(k.scene, k.accel, k.scene.camera, {kRes, kRes, 32, {}}, 4, 0);
    const manylights::MatrixContext mc{&k.accel, r, 0.01f, 0.0f};
    const manylights::ColumnSketches s = manylights::sketch_columns(mc, pool, 16, 4);
    const auto x = manylights::cluster_columns(s, 40, 4), y = manylights::cluster_columns(s, 40, 4);
    ASSERT_EQ(x.size(), y.size());
    for (size_t i = 0; i < x.size(); ++i)
        EXPECT_EQ(x[i].columns, y[i].columns);
}

// A camera that sees the box through a small part of its image (a wide field of view from its
// opening): most of one grid's R rays miss, and the grid is refined until about R rows land on
// the box, spread over the part of the image it covers.
TEST(RowColumn, RowsLandOnWhatTheCameraSees) {
    const Cornell& c = cornell();
    scene::Camera wide = c.scene.camera;
    wide.yfov = 2.2f;
    // One grid of 64 rays: fewer than half of them find the box.
    size_t hits = 0;
    for (int j = 0; j < 8; ++j) {
        for (int i = 0; i < 8; ++i) {
            const scene::CameraRay cr = scene::generate_camera_ray(
                wide, kRes, kRes, Vec2((float(i) + 0.5f) * kRes / 8, (float(j) + 0.5f) * kRes / 8));
            hits += c.accel.occluded(trace::Ray{cr.origin, cr.direction}) ? 1 : 0;
        }
    }
    EXPECT_LT(hits, 32u) << "the box covers most of the image: nothing to refine";
    const uint32_t wanted = 64;
    const std::vector<manylights::Row> rows =
        manylights::make_rows(c.scene, c.accel, wide, {kRes, kRes, int(wanted), {}}, 3, 0);
    std::printf("%zu rows for %u asked, %zu of 64 rays on the box\n", rows.size(), wanted, hits);
    // The refined grid's count varies by a few rows about R (its cells on the box's outline).
    EXPECT_GE(double(rows.size()), 0.8 * manylights::kRowsFound * wanted);
    EXPECT_LE(rows.size(), 2u * wanted);
}

// With at least as many clusters as columns every VPL is its own representative, unscaled: the
// pool's image to the bit, through the clustering and through the sampler.
TEST(RowColumn, AClusterPerVplIsThePool) {
    const std::vector<light::Vpl> pool = pool_of(96, 13);
    const manylights::ColumnSketches s = cornell_sketches(pool, 16, 2);
    Rng rng(1, 0);
    std::vector<light::Vpl> reps;
    manylights::append_representatives(manylights::cluster_columns(s, 96, 2), s.norms, pool, 0.1f,
                                       rng, reps);
    ASSERT_TRUE(same_vpls(reps, pool));
    manylights::RowColumnSampler rc = sampler_with(16, 96, 3, 96);
    std::vector<light::Vpl> v = pool;
    rc.reduce(v);
    ASSERT_TRUE(same_vpls(v, pool));
    const Image a = oracle(pool), b = oracle(reps);
    for (size_t i = 0; i < a.pixels().size(); ++i)
        ASSERT_EQ(a.pixels()[i], b.pixels()[i]) << i;
}

// The two stages lower the cluster cost (column_clustering.h) the representatives' error on the
// rows is: more clusters, less cost, and far below one cluster or clusters cut in pool order.
TEST(RowColumn, ClusteringLowersTheCost) {
    const std::vector<light::Vpl> pool = pool_of(1024, 17);
    const manylights::ColumnSketches s = cornell_sketches(pool, 64, 6);
    auto total = [&](const std::vector<manylights::Cluster>& clusters) {
        return manylights::clusters_cost(s, clusters);
    };
    std::vector<manylights::Cluster> in_order(64);
    for (uint32_t j = 0; j < pool.size(); ++j)
        in_order[j * 64 / pool.size()].columns.push_back(j);
    const double one = total({manylights::Cluster{in_order[0].columns, true}});
    const double c16 = total(manylights::cluster_columns(s, 16, 1));
    const double c64 = total(manylights::cluster_columns(s, 64, 1));
    std::printf("cost: pool-order 64 %.4g, clustered 16 %.4g, 64 %.4g\n", total(in_order), c16,
                c64);
    EXPECT_LT(c64, c16);
    EXPECT_LT(c64, 0.5 * total(in_order));
    EXPECT_GT(one, 0.0);
}

// Past kExhaustiveCentres sampled centres (C/2 > 1 024) each column looks for its centre among a
// few groups (nearest_centre.h): the clusters still hold every column once, and more of them
// still cost less.
TEST(RowColumn, ManyClustersHoldEveryColumnOnceAndLowerTheCost) {
    const std::vector<light::Vpl> pool = pool_of(8192, 21);
    const manylights::ColumnSketches s = cornell_sketches(pool, 64, 7);
    std::vector<double> costs;
    for (const uint32_t count : {1024u, 2560u, 4096u}) {  // 512, 1 280 and 2 048 centres
        const std::vector<manylights::Cluster> clusters = manylights::cluster_columns(s, count, 2);
        EXPECT_LE(clusters.size(), count);
        std::vector<int> held(pool.size(), 0);
        for (const auto& k : clusters)
            for (uint32_t j : k.columns)
                ++held[j];
        for (size_t j = 0; j < held.size(); ++j)
            ASSERT_EQ(held[j], 1) << "column " << j << " with " << count << " clusters";
        costs.push_back(manylights::clusters_cost(s, clusters));
    }
    std::printf("cost: 1024 clusters %.4g, 2560 %.4g, 4096 %.4g\n", costs[0], costs[1], costs[2]);
    EXPECT_LT(costs[1], costs[0]);
    EXPECT_LT(costs[2], costs[1]);
}

// Clusters of bounded size (column_clustering.h): the two rooms' far-room VPLs, which the rows
// of the near room barely see, have nearly parallel sketches and gather by the hundred on the
// cost alone. Every cluster of seen columns holds at most kLargestCluster times their mean
// (rounded up), the bound the splitting keeps.
TEST(RowColumn, NoClusterHoldsMoreThanItsShareOfTheColumns) {
    const scene::Scene scene = scene::load_scene(MVPL_ASSETS_DIR "/two-room/two-room.gltf");
    const trace::Accel accel(scene);
    const light::LightSampler lights(scene);
    const std::vector<light::Vpl> pool = stream_pool(scene, accel, lights, 8192, 11);
    const std::vector<manylights::Row> rows =
        manylights::make_rows(scene, accel, scene.camera, {32, 32, 64, {}}, 11, 0);
    const float d_min = light::kDefaultClamp * scene.bounds().diagonal();
    const manylights::MatrixContext mc{&accel, rows, d_min * d_min, 0.0f};
    const manylights::ColumnSketches s = manylights::sketch_columns(mc, pool, 16, 11);
    // Unbounded, the largest held 250 and 238 columns here, against bounds of 128 and 65.
    for (const uint32_t count : {512u, 1024u}) {
        const std::vector<manylights::Cluster> clusters = manylights::cluster_columns(s, count, 3);
        size_t seen_columns = 0, seen_clusters = 0, largest = 0, columns = 0;
        for (const manylights::Cluster& k : clusters) {
            columns += k.columns.size();
            if (!k.seen) continue;
            ++seen_clusters;
            seen_columns += k.columns.size();
            largest = std::max(largest, k.columns.size());
        }
        ASSERT_EQ(columns, pool.size());
        ASSERT_EQ(clusters.size(), count);
        // The seen clusters are the C less the unseen ones (cluster_columns).
        const double bound =
            std::ceil(manylights::kLargestCluster * double(seen_columns) / double(seen_clusters));
        std::printf("%u clusters: %zu seen columns in %zu, the largest %zu (bound %.0f)\n", count,
                    seen_columns, seen_clusters, largest, bound);
        EXPECT_LE(double(largest), bound);
    }
}

// The integrator's hook: with a cluster per VPL the oracle image is the one without row-column
// sampling; with fewer it shades fewer VPLs than the stream gave.
TEST(RowColumn, IntegratorHook) {
    const Cornell& c = cornell();
    integrator::Estimate e;
    e.render.width = e.render.height = kRes;
    e.compensate = false;
    e.caustics = false;
    e.sampling.seed = 3;
    auto run = [&](uint32_t pool, uint32_t clusters, integrator::IntegratorStats* stats) {
        integrator::Estimate x = e;
        x.many_lights.pool = pool;
        x.many_lights.rows = 16;
        x.many_lights.clusters = clusters;
        const integrator::SceneView view{&c.scene, &c.accel, &c.lights, &c.scene.camera};
        integrator::VplIntegrator it(view, nullptr, 1, nullptr);
        it.begin(view, x, integrator::Pacing::Fixed);
        it.advance(64);
        it.advance(64);
        Image image = it.finish();
        if (stats) *stats = it.stats();
        return image;
    };
    integrator::IntegratorStats stats;
    const Image plain = run(0, 1, nullptr), same = run(64, 64, nullptr);
    for (size_t i = 0; i < plain.pixels().size(); ++i)
        ASSERT_EQ(plain.pixels()[i], same.pixels()[i]) << i;
    run(128, 16, &stats);
    EXPECT_GT(stats.vpls, 128u);
    EXPECT_LE(stats.shaded, 4 * 17u);  // two chunks of ≥ 128 VPLs, ≤ 2 pools each
    EXPECT_LT(stats.shaded, stats.vpls);
}

}  // namespace
}  // namespace mvpl
