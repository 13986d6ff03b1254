// Hemicubes (issue 14): Area and Surface VPLs draw only the texels of each shadow-cube face that
// their lit hemisphere can reach (engine/render/hemicube.h). On the CPU: every direction on the
// lit side falls in the drawn rectangle; on the GPU: the image is the same to the bit as with
// whole faces, since the shading pass never reads a texel outside it.
#include <gtest/gtest.h>

#include <random>

#include "engine/render/hemicube.h"
#include "engine/render/vpl_renderer.h"
#include "engine/scene/scene_loader.h"
#include "tests/gpu/gpu_test.h"
#include "tests/support/scene_builder.h"
#include "tests/support/vpl_render.h"

namespace mvpl::render {
namespace {

// The face and texel that direction w falls in, as shadow_lookup.glsl's cube_texel finds
// them (major axis, then (s_c, t_c) / |m_a|).
std::pair<uint32_t, glm::uvec2> texel_of(const Vec3& w, uint32_t res) {
    const Vec3 a = glm::abs(w);
    uint32_t face;
    float s, t, m;
    if (a.x >= a.y && a.x >= a.z) {
        face = w.x < 0.0f ? 1 : 0;
        m = a.x;
        s = w.x < 0.0f ? w.z : -w.z;
        t = -w.y;
    } else if (a.y >= a.z) {
        face = w.y < 0.0f ? 3 : 2;
        m = a.y;
        s = w.x;
        t = w.y < 0.0f ? -w.z : w.z;
    } else {
        face = w.z < 0.0f ? 5 : 4;
        m = a.z;
        s = w.z < 0.0f ? -w.x : w.x;
        t = -w.y;
    }
    const auto texel = [&](float v) {
        return uint32_t(
            std::clamp(std::floor((v / m * 0.5f + 0.5f) * float(res)), 0.0f, float(res - 1)));
    };
    return {face, {texel(s), texel(t)}};
}

TEST(Hemicube, TheRectangleHoldsEveryDirectionOnTheLitSide) {
    std::mt19937 rng(5);
    std::normal_distribution<float> g;
    for (const uint32_t res : {8u, 64u, 256u}) {
        for (int trial = 0; trial < 200; ++trial) {
            Vec3 n = glm::normalize(Vec3(g(rng), g(rng), g(rng)));
            if (trial < 6) n = Vec3(0.0f), n[trial / 2] = trial % 2 == 0 ? 1.0f : -1.0f;
            for (int k = 0; k < 200; ++k) {
                Vec3 w = glm::normalize(Vec3(g(rng), g(rng), g(rng)));
                if (glm::dot(n, w) < 0.0f) w = -w;
                const auto [face, texel] = texel_of(w, res);
                const std::optional<FaceRect> rect = lit_face_rect(n, face, res);
                ASSERT_TRUE(rect.has_value()) << "face " << face;
                EXPECT_GE(texel.x, rect->x);
                EXPECT_LT(texel.x, rect->x + rect->width);
                EXPECT_GE(texel.y, rect->y);
                EXPECT_LT(texel.y, rect->y + rect->height);
            }
        }
    }
}

// An axis-aligned normal gets Cohen & Greenberg's hemicube: the front face whole, the back face
// not at all, each side face half (plus the margin).
TEST(Hemicube, AnAxisAlignedNormalDrawsOneFaceAndFourHalves) {
    constexpr uint32_t kRes = 64;
    const Vec3 up(0.0f, 1.0f, 0.0f);  // faces: +Y front, −Y back
    ASSERT_TRUE(lit_face_rect(up, 2, kRes).has_value());
    EXPECT_EQ(lit_face_rect(up, 2, kRes)->width * lit_face_rect(up, 2, kRes)->height, kRes * kRes);
    EXPECT_FALSE(lit_face_rect(up, 3, kRes).has_value());
    for (const uint32_t side : {0u, 1u, 4u, 5u}) {
        const std::optional<FaceRect> r = lit_face_rect(up, side, kRes);
        ASSERT_TRUE(r.has_value());
        EXPECT_EQ(r->width, kRes);
        // +Y is t = −1, the rows from 0: half the face, the row that starts on the horizon,
        // and the margin.
        EXPECT_EQ(r->y, 0u);
        EXPECT_EQ(r->height, kRes / 2 + 1 + kHemicubeMargin);
    }
}

using HemicubeTest = gpu::testing::GpuTest;

// The Cornell box (axis-aligned walls: half faces) with a sphere (every normal): Monte Carlo
// VPLs of depth 6, mostly surface VPLs, with hemicubes and with whole faces.
TEST_F(HemicubeTest, ImagesAreTheSameAsWithWholeFaces) {
    scene::Scene s = scene::load_scene(MVPL_ASSETS_DIR "/cornell-box/cbox.gltf");
    const scene::Bounds b = s.bounds();
    const Vec3 extent = b.hi - b.lo;
    s.meshes.push_back(test::make_icosphere(b.lo + Vec3(0.4f, 0.3f, 0.5f) * extent,
                                            0.15f * extent.x, 3, false, 0));
    const light::VplSet vpls = test::monte_carlo_vpls(s, 32, 6, 9);
    size_t surface = 0;
    for (const light::Vpl& v : vpls.vpls)
        surface += v.type == light::VplType::Surface ? 1 : 0;
    ASSERT_GT(surface, 20u);
    VplRenderer renderer(context(), s);
    for (const uint32_t shadow_res : {16u, 128u}) {
        RenderOptions o;
        o.width = o.height = 48;
        o.shadow_resolution = shadow_res;
        o.hemicube = true;
        RenderTimings hemi_timings;
        const Image hemi = renderer.render(vpls, o, &hemi_timings);
        o.hemicube = false;
        RenderTimings full_timings;
        const Image full = renderer.render(vpls, o, &full_timings);
        // An axis-aligned normal draws 1 + 4 · (res/2 + 3)/res faces instead of 5: 0.62 of the
        // texels at 128², 0.75 at 16² (the margin weighs more); other normals draw less.
        const double ratio =
            double(hemi_timings.shadow_texels) / double(full_timings.shadow_texels);
        EXPECT_LT(ratio, shadow_res >= 128 ? 0.7 : 0.8) << "shadow faces " << shadow_res;
        RecordProperty("texel_ratio_" + std::to_string(shadow_res), std::to_string(ratio));
        size_t differing = 0;
        for (size_t i = 0; i < full.pixels().size(); ++i)
            differing += hemi.pixels()[i] != full.pixels()[i] ? 1 : 0;
        EXPECT_EQ(differing, 0u) << "shadow faces " << shadow_res;
        EXPECT_GT(full.mean().r, 0.0f);
    }
}

}  // namespace
}  // namespace mvpl::render
