// Texture sampling (wrap modes, filters) and KHR_texture_transform.
#include <gtest/gtest.h>

#include <limits>

#include "engine/scene/texture.h"

namespace mvpl::scene {
namespace {

// 2×2: top row red, green; bottom row blue, white.
Texture two_by_two(Filter filter, Wrap wrap_s = Wrap::Repeat, Wrap wrap_t = Wrap::Repeat) {
    Texture t;
    t.width = 2;
    t.height = 2;
    t.texels = {Vec4(1, 0, 0, 1), Vec4(0, 1, 0, 1), Vec4(0, 0, 1, 1), Vec4(1, 1, 1, 1)};
    t.filter = filter;
    t.wrap_s = wrap_s;
    t.wrap_t = wrap_t;
    return t;
}

void expect_vec4_near(const Vec4& a, const Vec4& b) {
    for (int i = 0; i < 4; ++i)
        EXPECT_NEAR(a[i], b[i], 1e-6f) << "component " << i;
}

const Vec4 kRed(1, 0, 0, 1), kGreen(0, 1, 0, 1), kBlue(0, 0, 1, 1), kWhite(1, 1, 1, 1);

TEST(Texture, NearestPicksTheTexelUnderUvWithRowZeroAtTheTop) {
    const Texture t = two_by_two(Filter::Nearest);
    expect_vec4_near(t.sample(Vec2(0.25f, 0.25f)), kRed);
    expect_vec4_near(t.sample(Vec2(0.75f, 0.25f)), kGreen);
    expect_vec4_near(t.sample(Vec2(0.25f, 0.75f)), kBlue);
    expect_vec4_near(t.sample(Vec2(0.75f, 0.75f)), kWhite);
}

TEST(Texture, RepeatWrapsBothWays) {
    const Texture t = two_by_two(Filter::Nearest);
    expect_vec4_near(t.sample(Vec2(1.25f, 0.25f)), kRed);
    expect_vec4_near(t.sample(Vec2(-0.25f, 0.25f)), kGreen);
    expect_vec4_near(t.sample(Vec2(0.25f, -0.25f)), kBlue);
    expect_vec4_near(t.sample(Vec2(1.0f, 1.0f)), kRed);
}

TEST(Texture, ClampToEdgeHoldsTheBorderTexel) {
    const Texture t = two_by_two(Filter::Nearest, Wrap::ClampToEdge, Wrap::ClampToEdge);
    expect_vec4_near(t.sample(Vec2(5.0f, 0.25f)), kGreen);
    expect_vec4_near(t.sample(Vec2(-3.0f, 0.25f)), kRed);
    expect_vec4_near(t.sample(Vec2(0.25f, 9.0f)), kBlue);
}

TEST(Texture, MirroredRepeatReflectsEveryOtherPeriod) {
    const Texture t = two_by_two(Filter::Nearest, Wrap::MirroredRepeat, Wrap::Repeat);
    expect_vec4_near(t.sample(Vec2(1.25f, 0.25f)), kGreen);  // 2 − 1.25 = 0.75
    expect_vec4_near(t.sample(Vec2(1.75f, 0.25f)), kRed);
    expect_vec4_near(t.sample(Vec2(2.25f, 0.25f)), kRed);  // next period, not mirrored
    expect_vec4_near(t.sample(Vec2(-0.25f, 0.25f)), kRed);
}

TEST(Texture, LinearInterpolatesBetweenTexelCentres) {
    const Texture t = two_by_two(Filter::Linear, Wrap::ClampToEdge, Wrap::ClampToEdge);
    expect_vec4_near(t.sample(Vec2(0.25f, 0.25f)), kRed);
    expect_vec4_near(t.sample(Vec2(0.5f, 0.25f)), 0.5f * (kRed + kGreen));
    expect_vec4_near(t.sample(Vec2(0.5f, 0.5f)), 0.25f * (kRed + kGreen + kBlue + kWhite));
    expect_vec4_near(t.sample(Vec2(0.0f, 0.25f)), kRed);  // clamped: no bleeding from the right
}

TEST(Texture, LinearWithRepeatBlendsAcrossTheSeam) {
    const Texture t = two_by_two(Filter::Linear);
    expect_vec4_near(t.sample(Vec2(0.0f, 0.25f)), 0.5f * (kRed + kGreen));
    expect_vec4_near(t.sample(Vec2(1.0f, 0.25f)), 0.5f * (kRed + kGreen));
}

TEST(Texture, NonFiniteAndHugeCoordinatesAreSafe) {
    const float inf = std::numeric_limits<float>::infinity();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (Wrap wrap : {Wrap::Repeat, Wrap::ClampToEdge, Wrap::MirroredRepeat}) {
        for (Filter filter : {Filter::Nearest, Filter::Linear}) {
            const Texture t = two_by_two(filter, wrap, wrap);
            for (float u : {nan, inf, -inf, 1e30f, -1e30f, 3e9f}) {
                const Vec4 v = t.sample(Vec2(u, u));
                EXPECT_TRUE(std::isfinite(v.x) && std::isfinite(v.w));
            }
        }
    }
}

TEST(Texture, EmptyTextureSamplesAsNeutralWhite) {
    const Texture t;
    expect_vec4_near(t.sample(Vec2(0.5f)), Vec4(1.0f));
}

TEST(TextureRef, DefaultTransformIsIdentity) {
    const TextureRef ref;
    EXPECT_FALSE(ref.valid());
    const Vec2 uv = ref.transform(Vec2(0.3f, 0.7f));
    EXPECT_FLOAT_EQ(uv.x, 0.3f);
    EXPECT_FLOAT_EQ(uv.y, 0.7f);
}

TEST(TextureRef, ScalesThenRotatesThenOffsets) {
    TextureRef ref;
    ref.offset = Vec2(0.5f, 0.25f);
    ref.scale = Vec2(2.0f, 3.0f);
    const Vec2 plain = ref.transform(Vec2(1.0f, 1.0f));
    EXPECT_FLOAT_EQ(plain.x, 2.5f);
    EXPECT_FLOAT_EQ(plain.y, 3.25f);
    // Rotation rows [cos, sin; -sin, cos] (KHR_texture_transform as implemented and tested by the
    // sample model): a quarter turn takes u = 1 to v = −1.
    ref.rotation = kPi / 2.0f;
    ref.offset = Vec2(0.0f);
    ref.scale = Vec2(1.0f);
    const Vec2 turned = ref.transform(Vec2(1.0f, 0.0f));
    EXPECT_NEAR(turned.x, 0.0f, 1e-6f);
    EXPECT_NEAR(turned.y, -1.0f, 1e-6f);
    const Vec2 turned_v = ref.transform(Vec2(0.0f, 1.0f));
    EXPECT_NEAR(turned_v.x, 1.0f, 1e-6f);
    EXPECT_NEAR(turned_v.y, 0.0f, 1e-6f);
    // All three: T · R · S.
    ref.rotation = 0.3f;
    ref.scale = Vec2(2.0f, 3.0f);
    ref.offset = Vec2(0.5f, 0.25f);
    const Vec2 s(0.2f * 2.0f, 0.4f * 3.0f);
    const Vec2 all = ref.transform(Vec2(0.2f, 0.4f));
    EXPECT_NEAR(all.x, std::cos(0.3f) * s.x + std::sin(0.3f) * s.y + 0.5f, 1e-6f);
    EXPECT_NEAR(all.y, -std::sin(0.3f) * s.x + std::cos(0.3f) * s.y + 0.25f, 1e-6f);
}

}  // namespace
}  // namespace mvpl::scene
