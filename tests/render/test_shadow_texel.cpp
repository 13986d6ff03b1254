// The plane channel of a shadow texel (shaders/shared/shadow_map.h): the code a normal packs into
// survives a float exactly, does not depend on the normal's sign or length, and decodes to the
// normal within the quantisation's step, over the whole sphere.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "engine/core/math.h"
#include "shaders/shared/shadow_map.h"

namespace mvpl::shared {
namespace {

// The decoded normal as shadow_lookup.glsl's occluder_plane_normal() forms it, made unit.
Vec3 decoded(float code) {
    const float s = occluder_plane_s(code);
    const float t = occluder_plane_t(code);
    const float px = (s + t) * 0.5f;
    const float py = (s - t) * 0.5f;
    return glm::normalize(Vec3(px, py, 1.0f - std::abs(px) - std::abs(py)));
}

TEST(ShadowTexel, PlaneCodesDecodeWithinTheirStep) {
    std::mt19937 rng(7);
    std::normal_distribution<float> gauss;
    float worst = 0.0f;
    for (int i = 0; i < 100000; ++i) {
        const Vec3 n = glm::normalize(Vec3(gauss(rng), gauss(rng), gauss(rng)));
        const float code = occluder_plane_code(n.x, n.y, n.z);
        ASSERT_GE(code, 1.0f);
        ASSERT_LE(code, 16777216.0f);  // 2²⁴: every code is a float's exact integer
        ASSERT_EQ(code, std::floor(code));
        // The plane, not the side: −n gives the same code; a longer normal (a larger triangle's
        // derivatives) the same up to rounding across a cell's edge.
        EXPECT_EQ(occluder_plane_code(-n.x, -n.y, -n.z), code);
        const Vec3 m = decoded(code);
        const Vec3 longer = decoded(occluder_plane_code(3.0f * n.x, 3.0f * n.y, 3.0f * n.z));
        for (const Vec3& got : {m, longer})
            worst = std::max(worst, std::acos(std::min(1.0f, std::abs(glm::dot(got, n)))));
    }
    // Rounding s and t to a step of 2/4095 moves each by at most 1/4095, so p's coordinates by at
    // most 1/4095 each and n = (p, 1 − |p|₁) by at most √6/4095, against its smallest length
    // 1/√3: at most √18/4095 = 1.04·10⁻³ rad.
    EXPECT_LT(worst, 1.04e-3f);
    EXPECT_GT(worst, 1e-5f);  // it is quantised
}

TEST(ShadowTexel, ADegenerateTriangleHasNoPlane) {
    EXPECT_EQ(occluder_plane_code(0.0f, 0.0f, 0.0f), kNoOccluderPlane);
    EXPECT_NE(occluder_plane_code(0.0f, 0.0f, 1e-30f), kNoOccluderPlane);
}

}  // namespace
}  // namespace mvpl::shared
