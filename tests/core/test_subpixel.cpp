// The sub-pixel sequence (engine/core/subpixel.h) that the GPU renderer and the CPU oracle share.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <utility>

#include "engine/core/subpixel.h"

namespace mvpl {
namespace {

TEST(Subpixel, PositionZeroIsThePixelCentre) {
    EXPECT_EQ(subpixel_position(0), Vec2(0.5f, 0.5f));
    EXPECT_EQ((SubpixelSchedule{false, 4}.position(7)), Vec2(0.5f, 0.5f));
}

// Every prefix of 2^m positions is a (0,m,2)-net: one point in each dyadic box 2^−a × 2^−(m−a).
TEST(Subpixel, PowerOfTwoPrefixesAreStratifiedInEveryDyadicBox) {
    for (int m = 0; m <= 10; ++m) {
        const uint32_t n = 1u << m;
        for (int a = 0; a <= m; ++a) {
            std::set<std::pair<uint32_t, uint32_t>> boxes;
            for (uint32_t i = 0; i < n; ++i) {
                const Vec2 p = subpixel_position(i);
                ASSERT_GE(p.x, 0.0f);
                ASSERT_LT(p.x, 1.0f);
                ASSERT_GE(p.y, 0.0f);
                ASSERT_LT(p.y, 1.0f);
                boxes.insert(
                    {uint32_t(p.x * float(1u << a)), uint32_t(p.y * float(1u << (m - a)))});
            }
            EXPECT_EQ(boxes.size(), n) << "m " << m << ", a " << a;
        }
    }
}

// The property the renderer needs: the fraction of positions on one side of an edge through the
// pixel converges to the covered area, here for a slanted half-plane u + v/2 ≥ 0.8 (area 0.45).
TEST(Subpixel, TheFractionBehindASlantedEdgeConvergesToItsArea) {
    double previous_error = 1.0;
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
        EXPECT_LE(error, previous_error + 1e-12) << n;
        previous_error = error;
    }
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
