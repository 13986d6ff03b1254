#include <gtest/gtest.h>

#include "engine/core/rng.h"
#include "engine/core/sampling.h"

namespace mvpl {
namespace {

TEST(Rng, DeterministicStreamsAndRange) {
    Rng a(42, 3), b(42, 3), c(42, 4);
    int same = 0;
    for (int i = 0; i < 1000; ++i) {
        const float x = a.next_float();
        EXPECT_EQ(x, b.next_float());
        same += x == c.next_float();
        EXPECT_GE(x, 0.0f);
        EXPECT_LT(x, 1.0f);
    }
    EXPECT_LT(same, 5);
}

// Each warp's mean of a known function matches its integral: E[g(X)/pdf(X)] over the domain.
TEST(Sampling, CosineHemisphereIntegratesCosineToPi) {
    Rng rng(1, 1);
    double sum = 0.0;
    constexpr int kN = 200000;
    for (int i = 0; i < kN; ++i) {
        const Vec3 w = sample_cosine_hemisphere(Vec2(rng.next_float(), rng.next_float()));
        ASSERT_NEAR(glm::length(w), 1.0f, 1e-5f);
        ASSERT_GE(w.z, 0.0f);
        sum += w.z / cosine_hemisphere_pdf(w.z);
    }
    EXPECT_NEAR(sum / kN, kPi, 1e-3);
}

TEST(Sampling, UniformSphereAndConeMeans) {
    Rng rng(2, 1);
    constexpr int kN = 200000;
    DVec3 mean(0.0);
    double cone_z = 0.0;
    const float cos_max = 0.5f;
    for (int i = 0; i < kN; ++i) {
        const Vec2 u(rng.next_float(), rng.next_float());
        mean += DVec3(sample_uniform_sphere(u));
        const Vec3 c = sample_uniform_cone(u, cos_max);
        ASSERT_GE(c.z, cos_max - 1e-6f);
        cone_z += c.z;
    }
    mean /= double(kN);
    EXPECT_LT(glm::length(mean), 0.01);
    // Uniform in cos θ on [cos_max, 1]: mean (1 + cos_max) / 2.
    EXPECT_NEAR(cone_z / kN, 0.75, 2e-3);
}

TEST(Sampling, TriangleIsUniform) {
    Rng rng(3, 1);
    constexpr int kN = 100000;
    int in_first_half = 0;
    Vec2 mean(0.0f);
    for (int i = 0; i < kN; ++i) {
        const Vec2 b = sample_uniform_triangle(Vec2(rng.next_float(), rng.next_float()));
        ASSERT_GE(b.x, 0.0f);
        ASSERT_GE(b.y, 0.0f);
        ASSERT_LE(b.x + b.y, 1.0f + 1e-6f);
        mean += b;
        // The median from p2 (b1 = (1 − b2) / 2) halves the triangle's area.
        in_first_half += b.x < 0.5f - 0.5f * b.y ? 1 : 0;
    }
    mean /= float(kN);
    // The centroid has barycentrics (1/3, 1/3).
    EXPECT_NEAR(mean.x, 1.0f / 3.0f, 5e-3f);
    EXPECT_NEAR(mean.y, 1.0f / 3.0f, 5e-3f);
    EXPECT_NEAR(double(in_first_half) / kN, 0.5, 1e-2);
}

TEST(Sampling, PowerHeuristic) {
    EXPECT_FLOAT_EQ(power_heuristic(1.0f, 1.0f), 0.5f);
    EXPECT_FLOAT_EQ(power_heuristic(0.0f, 0.0f), 0.0f);
    EXPECT_NEAR(power_heuristic(3.0f, 1.0f), 0.9f, 1e-6f);
}

}  // namespace
}  // namespace mvpl
