// The sub-pixel sequence (engine/core/subpixel.h) that the GPU renderer and the CPU oracle share.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/core/subpixel.h"

namespace mvpl {
namespace {

TEST(Subpixel, PositionZeroIsThePixelCentre) {
    EXPECT_EQ(subpixel_position(0), Vec2(0.5f, 0.5f));
    EXPECT_EQ((SubpixelSchedule{false, 4}.position(7)), Vec2(0.5f, 0.5f));
}

// Antithetic pairs: every odd-length prefix has its mean position exactly at the centre, and
// every position lies inside the pixel.
TEST(Subpixel, OddPrefixesAreCentredOnThePixel) {
    double sx = 0.0, sy = 0.0;
    for (uint64_t i = 0; i < 2049; ++i) {
        const Vec2 p = subpixel_position(i);
        ASSERT_GE(p.x, 0.0f);
        ASSERT_LT(p.x, 1.0f);
        ASSERT_GE(p.y, 0.0f);
        ASSERT_LT(p.y, 1.0f);
        sx += p.x;
        sy += p.y;
        if (i % 2 == 0) {
            EXPECT_NEAR(sx / double(i + 1), 0.5, 1e-6) << i;
            EXPECT_NEAR(sy / double(i + 1), 0.5, 1e-6) << i;
        }
    }
    EXPECT_NE(subpixel_position(1), subpixel_position(3));
}

// The property the renderer needs: the fraction of positions on one side of an edge through the
// pixel converges to the covered area, here for a slanted half-plane u + v/2 ≥ 0.8 (area 0.45).
TEST(Subpixel, TheFractionBehindASlantedEdgeConvergesToItsArea) {
    for (const uint32_t n : {16u, 64u, 256u, 1024u}) {
        uint32_t inside = 0;
        for (uint32_t i = 0; i < n; ++i) {
            const Vec2 p = subpixel_position(i);
            if (p.x + 0.5f * p.y >= 0.8f) ++inside;
        }
        const double error = std::abs(double(inside) / n - 0.45);
        EXPECT_LT(error, 2.0 / std::sqrt(double(n))) << n;  // far better than random
        if (n >= 256) {
            EXPECT_LT(error, 0.01) << n;
        }
    }
}

// A seed's rotation moves every position, the first one off the centre, keeps the pairs
// antithetic about the centre and the positions inside the pixel; two seeds differ.
TEST(Subpixel, ARotationMovesEveryPositionAndKeepsThePairs) {
    const Vec2 u = subpixel_rotation(7);
    EXPECT_NE(u, subpixel_rotation(8));
    EXPECT_NE(subpixel_position(0, u), Vec2(0.5f));
    EXPECT_EQ(subpixel_position(5, Vec2(0.0f)), subpixel_position(5));
    const Vec2 first = subpixel_position(0, u);
    double sx = 0.0, sy = 0.0;
    int moved = 0;
    for (uint64_t i = 0; i < 1025; ++i) {
        const Vec2 p = subpixel_position(i, u);
        ASSERT_GE(p.x, 0.0f);
        ASSERT_LT(p.x, 1.0f);
        ASSERT_GE(p.y, 0.0f);
        ASSERT_LT(p.y, 1.0f);
        if (p != subpixel_position(i)) ++moved;
        if (i == 0) continue;
        sx += p.x;
        sy += p.y;
        if (i % 2 == 0) {  // the pairs after the first position are centred
            EXPECT_NEAR(sx / double(i), 0.5, 1e-6) << i;
            EXPECT_NEAR(sy / double(i), 0.5, 1e-6) << i;
        }
    }
    EXPECT_EQ(moved, 1025);
    EXPECT_NEAR(first.x, std::fmod(0.5f + u.x, 1.0f), 1e-6f);
    const SubpixelSchedule s{true, 32, u};
    EXPECT_EQ(s.position(3), subpixel_position(3, u));
}

// Why the first position moves (subpixel.h): over seeds, every position is uniform over the
// pixel, so a feature much smaller than a pixel is hit in proportion to its area. A square of
// area 10⁻⁴ at the centre, 32 positions per render: the expected share of renders that hit it is
// at most 32 · 10⁻⁴ = 0.32 %, so over 1024 seeds at most ~3 (Poisson, P(≥ 16) < 10⁻⁶); with the
// centre kept for every seed it was hit in all of them. The mean of the first position over the
// seeds is ½ within 4σ (σ = 1/√(12 · 1024) = 0.009).
TEST(Subpixel, OverSeedsAFeatureAtTheCentreIsHitInProportionToItsArea) {
    constexpr int kSeeds = 1024;
    int hits = 0;
    double mean_x = 0.0, mean_y = 0.0;
    for (int seed = 0; seed < kSeeds; ++seed) {
        const Vec2 u = subpixel_rotation(uint64_t(seed));
        const Vec2 first = subpixel_position(0, u);
        mean_x += first.x / kSeeds;
        mean_y += first.y / kSeeds;
        for (uint64_t i = 0; i < 32; ++i) {
            const Vec2 p = subpixel_position(i, u);
            if (std::abs(p.x - 0.5f) < 0.005f && std::abs(p.y - 0.5f) < 0.005f) {
                ++hits;
                break;
            }
        }
    }
    EXPECT_LT(hits, 16);
    EXPECT_NEAR(mean_x, 0.5, 0.036);
    EXPECT_NEAR(mean_y, 0.5, 0.036);
}

TEST(Subpixel, TheScheduleGroupsVplsAndCountsPositions) {
    const SubpixelSchedule s{true, 32};
    EXPECT_EQ(s.position_of(0), 0u);
    EXPECT_EQ(s.position_of(31), 0u);
    EXPECT_EQ(s.position_of(32), 1u);
    EXPECT_EQ(s.positions_after(0), 1u);  // an image with no VPL still has its first G-buffer
    EXPECT_EQ(s.positions_after(32), 1u);
    EXPECT_EQ(s.positions_after(33), 2u);
    EXPECT_EQ(s.position(1), subpixel_position(1));
    const SubpixelSchedule off{false, 32};
    EXPECT_EQ(off.position_of(1000), 0u);
    EXPECT_EQ(off.positions_after(1000), 1u);
}

}  // namespace
}  // namespace mvpl
