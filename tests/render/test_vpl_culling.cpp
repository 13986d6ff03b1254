// Per-batch VPL culling (issue 14, engine/render/vpl_culling.h): an Area or Surface VPL whose lit
// half-space holds no point of the view is neither drawn nor shaded. It must never drop a VPL
// whose light reaches the view, even through one small triangle, and the images must be the same
// to the bit with it on and off (with and without interleaving).
#include <gtest/gtest.h>

#include "engine/render/vpl_culling.h"
#include "engine/render/vpl_renderer.h"
#include "tests/gpu/gpu_test.h"
#include "tests/support/scene_builder.h"

namespace mvpl::render {
namespace {

using VplCullingTest = gpu::testing::GpuTest;

// A floor (y = 0) and, above it, one small triangle facing +X and tilted up, seen from +X.
scene::Scene floor_and_small_triangle() {
    scene::Scene s;
    s.materials = {test::diffuse_material(Rgb(0.7f))};
    s.meshes.push_back(test::make_quad(Vec3(-2, 0, -2), Vec3(0, 0, 4), Vec3(4, 0, 0), 0));
    scene::Mesh t = test::make_quad(Vec3(0.0f, 1.4f, -0.05f), Vec3(0.02f, 0.1f, 0.0f),
                                    Vec3(0.0f, 0.0f, 0.1f), 0);
    t.indices.resize(3);  // one triangle of the quad
    s.meshes.push_back(t);
    s.camera = test::look_at(Vec3(3.0f, 2.5f, 0.3f), Vec3(0.0f, 1.0f, 0.0f), 0.7f);
    s.has_camera = true;
    return s;
}

light::Vpl facing_up(const Vec3& position) {
    light::Vpl v;
    v.type = light::VplType::Surface;
    v.position = position;
    v.normal = v.shading_normal = Vec3(0, 1, 0);
    v.wi = glm::normalize(Vec3(0.2f, 1.0f, 0.1f));
    v.power = Rgb(2.0f);
    v.path_length = 1;
    return v;
}

// Below the triangle, facing up: the floor lies behind its plane, the triangle (y ≥ 1.4) in
// front. Its light reaches the view only through that triangle.
light::Vpl through_the_triangle() {
    return facing_up(Vec3(0.8f, 1.0f, 0.0f));
}
// Above everything, facing up: nothing in view lies in front of it.
light::Vpl above_everything() {
    return facing_up(Vec3(0.0f, 3.0f, 0.0f));
}

TEST(VplCulling, KeepsAVplThatReachesTheViewThroughOneSmallTriangle) {
    const scene::Scene s = floor_and_small_triangle();
    VplCulling culling(s);
    culling.set_view(s.camera, 64, 64);
    EXPECT_EQ(culling.visible_chunk_count(), 2u);
    EXPECT_TRUE(culling.may_reach_view(through_the_triangle()));
    EXPECT_FALSE(culling.may_reach_view(above_everything()));
    // Without the triangle the first VPL reaches nothing either: the triangle is what kept it.
    scene::Scene floor_only = s;
    floor_only.meshes.pop_back();
    VplCulling floor_culling(floor_only);
    floor_culling.set_view(s.camera, 64, 64);
    EXPECT_FALSE(floor_culling.may_reach_view(through_the_triangle()));
}

TEST_F(VplCullingTest, TheTrianglesLightSurvivesAndImagesAreTheSame) {
    const scene::Scene s = floor_and_small_triangle();
    light::Vpl point;
    point.type = light::VplType::Point;
    point.position = Vec3(1.0f, 2.0f, 1.0f);
    point.power = Rgb(1.0f);
    const std::vector<light::Vpl> vpls = {through_the_triangle(), above_everything(), point};
    VplRenderer renderer(context(), s);
    RenderOptions o;
    o.width = o.height = 64;
    o.shadow_resolution = 64;
    o.clamp = 0.0f;
    // The triangle's light alone: some pixels see it.
    const Image alone = renderer.render({{through_the_triangle()}}, o);
    int lit = 0;
    for (const Rgb& p : alone.pixels())
        lit += max_component(p) > 0.0f ? 1 : 0;
    EXPECT_GT(lit, 0);
    // With interleaving, every lever of issue 14 is on (under the validation layers, as every
    // GpuTest): hemicubes and shadow culling by default.
    for (const uint32_t k : {1u, 2u}) {
        o.interleave = k;
        o.vpl_culling = true;
        RenderTimings culled_timings;
        const Image culled = renderer.render({vpls}, o, &culled_timings);
        o.vpl_culling = false;
        RenderTimings all_timings;
        const Image all = renderer.render({vpls}, o, &all_timings);
        EXPECT_EQ(culled_timings.culled_vpls, 1u);
        EXPECT_EQ(all_timings.culled_vpls, 0u);
        EXPECT_LT(culled_timings.shadow_texels, all_timings.shadow_texels);
        size_t differing = 0;
        for (size_t i = 0; i < all.pixels().size(); ++i)
            differing += culled.pixels()[i] != all.pixels()[i] ? 1 : 0;
        EXPECT_EQ(differing, 0u) << "interleave " << k;
    }
}

}  // namespace
}  // namespace mvpl::render
