// light::vpl_contribution against vpl.h's formulas in closed form: a point VPL and a surface VPL
// over a Lambertian floor, the clamping distance, occlusion, and a VPL below the receiver.
#include <gtest/gtest.h>

#include "engine/light/vpl_contribution.h"
#include "tests/support/scene_builder.h"

namespace mvpl::light {
namespace {

constexpr float kAlbedo = 0.5f;

// A Lambertian floor y = 0 (front face up); optionally a blocker quad at y = 1 facing down.
scene::Scene floor_scene(bool blocker) {
    scene::Scene s;
    s.materials.push_back(test::diffuse_material(Rgb(kAlbedo)));
    s.meshes.push_back(test::make_quad(Vec3(-2, 0, -2), Vec3(0, 0, 4), Vec3(4, 0, 0), 0));
    if (blocker) {
        s.meshes.push_back(test::make_quad(Vec3(-0.5f, 1, -0.5f), Vec3(1, 0, 0), Vec3(0, 0, 1), 0));
    }
    return s;
}

// The receiver at the floor point q, seen from straight above.
std::optional<Receiver> receiver_at(const scene::Scene& s, const trace::Accel& accel,
                                    const Vec3& q) {
    return make_receiver(s, accel, trace::Ray{q + Vec3(0, 3, 0), Vec3(0, -1, 0)});
}

Vpl point_vpl(const Vec3& p, const Rgb& power) {
    Vpl v;
    v.type = VplType::Point;
    v.position = p;
    v.power = power;
    return v;
}

// power · ρ/π · cos θ' / d².
TEST(VplContribution, PointVplOverALambertianFloorIsAnalytic) {
    const scene::Scene s = floor_scene(false);
    const trace::Accel accel(s);
    const Vec3 q(0.3f, 0.0f, -0.2f);
    const std::optional<Receiver> hit = receiver_at(s, accel, q);
    ASSERT_TRUE(hit);
    const Receiver& r = *hit;
    const Vec3 p(-0.4f, 0.8f, 0.5f);
    const Vpl v = point_vpl(p, Rgb(2.0f, 1.0f, 4.0f));
    const Rgb c = vpl_contribution(accel, r, prepare_vpl(v), 0.0f);
    const Vec3 d = p - q;
    const float d2 = glm::dot(d, d);
    const float cos_r = d.y / std::sqrt(d2);
    for (int k = 0; k < 3; ++k) {
        const float expected = v.power[k] * kAlbedo / kPi * cos_r / d2;
        EXPECT_NEAR(c[k], expected, 1e-5f * expected) << k;
    }
}

// max(d², d_min²) in the denominator: a VPL closer than d_min counts as at d_min.
TEST(VplContribution, ClampingBoundsTheDistance) {
    const scene::Scene s = floor_scene(false);
    const trace::Accel accel(s);
    const std::optional<Receiver> hit = receiver_at(s, accel, Vec3(0.0f));
    ASSERT_TRUE(hit);
    const Receiver& r = *hit;
    const Vpl v = point_vpl(Vec3(0.0f, 0.1f, 0.0f), Rgb(1.0f));
    const Rgb unclamped = vpl_contribution(accel, r, prepare_vpl(v), 0.0f);
    const Rgb clamped = vpl_contribution(accel, r, prepare_vpl(v), 0.25f);
    EXPECT_NEAR(unclamped.r, kAlbedo / kPi / 0.01f, 1e-3f);
    EXPECT_NEAR(clamped.r, kAlbedo / kPi / 0.25f, 1e-5f);
    // Beyond d_min clamping changes nothing.
    const Vpl far = point_vpl(Vec3(0.0f, 1.0f, 0.0f), Rgb(1.0f));
    EXPECT_EQ(vpl_contribution(accel, r, prepare_vpl(far), 0.25f),
              vpl_contribution(accel, r, prepare_vpl(far), 0.0f));
}

TEST(VplContribution, OccludedOrBelowTheReceiverGivesNothing) {
    const scene::Scene s = floor_scene(true);
    const trace::Accel accel(s);
    const std::optional<Receiver> hit = receiver_at(s, accel, Vec3(1.5f, 0.0f, 1.5f));
    ASSERT_TRUE(hit);
    const Receiver& r = *hit;
    // From (1.5, 0, 1.5) the segment to (0, 2, 0) crosses y = 1 at (0.75, 1, 0.75), beside the
    // blocker; the one to (-1.5, 2, -1.5) crosses at (0, 1, 0), through it.
    const Vpl seen = point_vpl(Vec3(0.0f, 2.0f, 0.0f), Rgb(1.0f));
    const Vpl hidden = point_vpl(Vec3(-1.5f, 2.0f, -1.5f), Rgb(1.0f));
    EXPECT_GT(vpl_contribution(accel, r, prepare_vpl(seen), 0.0f).r, 0.0f);
    EXPECT_EQ(vpl_contribution(accel, r, prepare_vpl(hidden), 0.0f), Rgb(0.0f));
    const Vpl below = point_vpl(Vec3(1.0f, -0.5f, 1.0f), Rgb(1.0f));
    EXPECT_EQ(vpl_contribution(accel, r, prepare_vpl(below), 0.0f), Rgb(0.0f));
}

// A surface VPL with a Lambertian closure of albedo a, normal n_j, lit from ω_in:
// power · ρ/π · cos θ' · a/π · max(0, n_j·ω) / d² (vpl.h, seed eq. 5).
TEST(VplContribution, SurfaceVplWeighsByItsOwnClosureAndCosine) {
    const scene::Scene s = floor_scene(false);
    const trace::Accel accel(s);
    const Vec3 q(0.0f);
    const std::optional<Receiver> hit = receiver_at(s, accel, q);
    ASSERT_TRUE(hit);
    const Receiver& r = *hit;
    Vpl v;
    v.type = VplType::Surface;
    v.position = Vec3(1.0f, 1.0f, 0.0f);
    v.normal = glm::normalize(Vec3(-1.0f, -0.5f, 0.0f));  // a wall facing the receiver
    v.shading_normal = v.normal;
    v.wi = v.normal;
    v.power = Rgb(3.0f);
    v.closure.base_color = Rgb(0.4f);
    v.closure.metallic = 0.0f;
    v.closure.specular = 0.0f;
    const Rgb c = vpl_contribution(accel, r, prepare_vpl(v), 0.0f);
    const Vec3 d = v.position - q;
    const float d2 = glm::dot(d, d);
    const Vec3 w = -d / std::sqrt(d2);  // VPL → receiver
    const float cos_r = d.y / std::sqrt(d2);
    const float cos_j = glm::dot(v.normal, w);
    const float expected = 3.0f * kAlbedo / kPi * cos_r * 0.4f / kPi * cos_j / d2;
    EXPECT_NEAR(c.r, expected, 1e-5f * expected);
    // Turned away from the receiver it lights nothing.
    v.normal = -v.normal;
    v.shading_normal = v.normal;
    v.wi = v.normal;
    EXPECT_EQ(vpl_contribution(accel, r, prepare_vpl(v), 0.0f), Rgb(0.0f));
}

}  // namespace
}  // namespace mvpl::light
