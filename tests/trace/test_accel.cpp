#include <gtest/gtest.h>

#include <vector>

#include "engine/core/rng.h"
#include "engine/core/sampling.h"
#include "engine/trace/accel.h"
#include "engine/trace/interaction.h"
#include "tests/support/scene_builder.h"

namespace mvpl {
namespace {

scene::Scene two_facing_quads(float scale, const Vec3& offset) {
    scene::Scene s;
    s.materials.push_back(test::diffuse_material(Rgb(0.5f)));
    // Floor facing up and ceiling facing down, one unit apart (times scale).
    s.meshes.push_back(test::make_quad(offset + scale * Vec3(-1, 0, -1), scale * Vec3(0, 0, 2),
                                       scale * Vec3(2, 0, 0), 0));
    s.meshes.push_back(test::make_quad(offset + scale * Vec3(-1, 1, -1), scale * Vec3(2, 0, 0),
                                       scale * Vec3(0, 0, 2), 0));
    return s;
}

TEST(Accel, ClosestHitAndInteraction) {
    const scene::Scene s = two_facing_quads(1.0f, Vec3(0.0f));
    const trace::Accel accel(s);
    const trace::Ray ray{Vec3(0.2f, 0.5f, 0.1f), Vec3(0, -1, 0)};
    const auto hit = accel.intersect(ray);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->mesh, 0);
    EXPECT_NEAR(hit->t, 0.5f, 1e-6f);
    const trace::SurfaceInteraction si = trace::make_interaction(s, *hit, ray);
    EXPECT_NEAR(si.p.x, 0.2f, 1e-6f);
    EXPECT_NEAR(si.p.y, 0.0f, 1e-6f);
    EXPECT_NEAR(si.ng.y, 1.0f, 1e-6f);
    EXPECT_TRUE(si.front_face);
    EXPECT_NEAR(glm::dot(si.dpdu, si.ns), 0.0f, 1e-6f);

    const trace::Ray up{Vec3(0.2f, 0.5f, 0.1f), Vec3(0, 1, 0)};
    const auto top = accel.intersect(up);
    ASSERT_TRUE(top);
    EXPECT_EQ(top->mesh, 1);
    const trace::Ray miss{Vec3(5.0f, 0.5f, 0.0f), Vec3(0, -1, 0)};
    EXPECT_FALSE(accel.intersect(miss));
    EXPECT_TRUE(accel.occluded(ray));
    EXPECT_FALSE(accel.occluded(miss));
    EXPECT_EQ(accel.ray_count(), 5u);
}

TEST(Accel, BackFaceHitIsReported) {
    const scene::Scene s = two_facing_quads(1.0f, Vec3(0.0f));
    const trace::Accel accel(s);
    const trace::Ray ray{Vec3(0.0f, -1.0f, 0.0f), Vec3(0, 1, 0)};
    const auto hit = accel.intersect(ray);
    ASSERT_TRUE(hit);
    EXPECT_FALSE(trace::make_interaction(s, *hit, ray).front_face);
}

// Rays leaving a surface point must not hit their own triangle and shadow rays between two
// mutually visible points must not be blocked, at millimetre and ten-kilometre scales and far from
// the origin, with no scene-dependent epsilon.
class SelfIntersection : public ::testing::TestWithParam<std::pair<float, float>> {};

TEST_P(SelfIntersection, NoSelfHitsAtAnyScale) {
    const float scale = GetParam().first;
    const Vec3 offset(GetParam().second);
    const scene::Scene s = two_facing_quads(scale, offset);
    const trace::Accel accel(s);
    Rng rng(7, 0);
    int self_hits = 0, blocked = 0;
    constexpr int kRays = 20000;
    for (int i = 0; i < kRays; ++i) {
        // A point on the floor, found by tracing (as the renderer does).
        const Vec3 origin = offset + scale * Vec3(rng.next_float() * 1.8f - 0.9f, 0.5f,
                                                  rng.next_float() * 1.8f - 0.9f);
        const trace::Ray down{origin, Vec3(0, -1, 0)};
        const auto hit = accel.intersect(down);
        ASSERT_TRUE(hit);
        const trace::SurfaceInteraction si = trace::make_interaction(s, *hit, down);
        Vec3 d = sample_cosine_hemisphere(Vec2(rng.next_float(), rng.next_float()));
        d = Frame(si.ng).to_world(d);
        const auto next =
            accel.intersect(trace::spawn_ray(si.p, si.ng, d, accel.coordinate_scale()));
        if (next && next->mesh == 0) ++self_hits;
        // Shadow ray to a point on the ceiling straight above (both surfaces face each other).
        const Vec3 target = si.p + Vec3(0.0f, scale, 0.0f);
        if (accel.occluded(
                trace::spawn_ray_to(si.p, si.ng, target, Vec3(0, -1, 0), accel.coordinate_scale())))
            ++blocked;
    }
    EXPECT_EQ(self_hits, 0);
    EXPECT_EQ(blocked, 0);
}

INSTANTIATE_TEST_SUITE_P(Scales, SelfIntersection,
                         ::testing::Values(std::make_pair(1e-3f, 0.0f), std::make_pair(1.0f, 0.0f),
                                           std::make_pair(1e4f, 0.0f), std::make_pair(1e-3f, 3.0f),
                                           std::make_pair(1e4f, 2e4f)));

// Rays traced together (a span, Embree's packets) are occluded exactly when each alone is: rays
// between random points around and between the two quads, some blocked by them and some not,
// counts that are not a multiple of a packet's width and an empty span.
TEST(Accel, OccludedTogetherIsOneByOne) {
    const scene::Scene s = two_facing_quads(1.0f, Vec3(0.0f));
    const trace::Accel accel(s);
    Rng rng(11, 0);
    auto point = [&] {
        return Vec3(rng.next_float() * 3.0f - 1.5f, rng.next_float() * 3.0f - 1.0f,
                    rng.next_float() * 3.0f - 1.5f);
    };
    for (const size_t count : {size_t(0), size_t(1), size_t(7), size_t(37), size_t(1000)}) {
        std::vector<trace::Ray> rays;
        for (size_t i = 0; i < count; ++i) {
            const Vec3 a = point(), b = point();
            rays.push_back(trace::Ray{a, b - a, i % 3 == 0 ? 0.5f : 1.0f});
        }
        std::vector<uint8_t> together(count, 2);
        const uint64_t before = accel.ray_count();
        accel.occluded(rays, together);
        EXPECT_EQ(accel.ray_count() - before, count);
        size_t blocked = 0;
        for (size_t i = 0; i < count; ++i) {
            ASSERT_EQ(together[i], accel.occluded(rays[i]) ? 1 : 0) << i << " of " << count;
            blocked += together[i];
        }
        if (count == 1000) {
            EXPECT_GT(blocked, 100u);
            EXPECT_LT(blocked, 900u);
        }
    }
}

TEST(Accel, IcosphereFacesInwards) {
    const scene::Mesh m = test::make_icosphere(Vec3(1, 2, 3), 2.0f, 2, true, 0);
    for (size_t t = 0; t < m.triangle_count(); ++t) {
        const Vec3 p0 = m.positions[m.indices[3 * t]], p1 = m.positions[m.indices[3 * t + 1]],
                   p2 = m.positions[m.indices[3 * t + 2]];
        const Vec3 n = glm::cross(p1 - p0, p2 - p0);
        ASSERT_LT(glm::dot(n, (p0 + p1 + p2) / 3.0f - Vec3(1, 2, 3)), 0.0f);
    }
    EXPECT_EQ(m.triangle_count(), 320u);
}

}  // namespace
}  // namespace mvpl
