// Clusters of bounded size (engine/manylights/column_clustering.h) over a family of synthetic
// pools: a share of the columns with one sketch direction (VPLs the rows cannot tell apart, whose
// cost is zero however many gather) and the rest spread over the sphere, across pool sizes,
// cluster counts, shares and norm spreads. Every column is in exactly one cluster and none holds
// more than ⌈kLargestCluster · N / C⌉ columns, the bound the splitting keeps when every column is
// seen.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/core/rng.h"
#include "engine/manylights/column_clustering.h"
#include "tests/manylights/standard_normal.h"

namespace mvpl {
namespace {

// N columns of `dims` entries: the first share · N along one direction, the rest Gaussian; norms
// log-uniform over `decades` decades, so that a few columns dominate the cost.
manylights::ColumnSketches pool_of(uint32_t n, double share, double decades, uint64_t seed) {
    manylights::ColumnSketches s;
    s.dims = 16;
    s.norms.resize(n);
    s.sketch.resize(size_t(n) * s.dims);
    Rng rng(seed, 0);
    std::vector<float> common(s.dims);
    for (float& v : common)
        v = manylights_test::standard_normal(rng);
    const auto alike = uint32_t(share * double(n));
    for (uint32_t j = 0; j < n; ++j) {
        s.norms[j] = float(std::pow(10.0, -decades * double(rng.next_float())));
        for (uint32_t k = 0; k < s.dims; ++k)
            s.sketch[size_t(j) * s.dims + k] =
                s.norms[j] * (j < alike ? common[k] : manylights_test::standard_normal(rng));
    }
    return s;
}

// One pool of the family into `count` clusters: every column held once, none above the bound.
void expect_bounded(uint32_t n, uint32_t count, double share, double decades) {
    const manylights::ColumnSketches s =
        pool_of(n, share, decades, n + n / count + uint64_t(share * 10));
    const std::vector<manylights::Cluster> clusters = manylights::cluster_columns(s, count, 7);
    const auto bound = size_t(std::ceil(manylights::kLargestCluster * double(n) / double(count)));
    std::vector<int> held(n, 0);
    size_t largest = 0;
    for (const manylights::Cluster& k : clusters) {
        ASSERT_TRUE(k.seen);
        largest = std::max(largest, k.columns.size());
        for (uint32_t j : k.columns)
            ++held[j];
    }
    ASSERT_LE(clusters.size(), count);
    for (uint32_t j = 0; j < n; ++j)
        ASSERT_EQ(held[j], 1) << "column " << j;
    EXPECT_LE(largest, bound) << "N " << n << ", C " << count << ", share " << share << ", "
                              << decades << " decades";
}

TEST(ColumnClustering, NoClusterLargerThanTheBoundOverAFamilyOfPools) {
    for (const uint32_t n : {1024u, 4096u, 16384u})
        for (const uint32_t divisor : {4u, 16u, 64u})
            for (const double share : {0.1, 0.5, 0.9})
                for (const double decades : {0.0, 3.0})
                    expect_bounded(n, n / divisor, share, decades);
}

}  // namespace
}  // namespace mvpl
