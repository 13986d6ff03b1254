// The Metropolis target follows the renderer's specular chains (issue 15, item 3): a camera that
// sees a wall only in a perfect mirror must find the same target as its mirror image looking at
// the wall directly, and nothing without chains (a point VPL cannot light a mirror).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "engine/light/vpl.h"
#include "engine/sampler/importance.h"
#include "engine/scene/camera.h"
#include "engine/trace/accel.h"
#include "tests/support/scene_builder.h"

namespace mvpl::sampler {
namespace {

constexpr float kYfov = 0.5f;
const Vec3 kEye(0.0f, 3.0f, 3.0f);
const Vec3 kTarget(0.0f, 0.0f, -1.0f);

// A wall at z = −8 facing +z, above y = 0, symmetric in x; with `mirror`, a white mirror floor
// (metallic 1, roughness 0: F = 1 at every angle) at y = 0.
scene::Scene wall_scene(bool mirror) {
    scene::Scene s;
    s.materials.push_back(test::diffuse_material(Rgb(0.8f)));
    s.meshes.push_back(test::make_quad(Vec3(-12.0f, 0.0f, -8.0f), Vec3(24.0f, 0.0f, 0.0f),
                                       Vec3(0.0f, 12.0f, 0.0f), 0));
    if (mirror) {
        scene::Material m;
        m.base_color = Rgb(1.0f);
        m.metallic = 1.0f;
        m.roughness = 0.0f;
        s.materials.push_back(m);
        s.meshes.push_back(test::make_quad(Vec3(-100.0f, 0.0f, 100.0f), Vec3(200.0f, 0.0f, 0.0f),
                                           Vec3(0.0f, 0.0f, -200.0f), 1));
    }
    return s;
}

ImportanceOptions options(bool chains) {
    ImportanceOptions o;
    o.points = 256;
    o.width = o.height = 64;
    o.clamp = 0.0f;  // the two scenes' diagonals differ
    o.seed = 7;
    if (chains) o.chains.max_roughness = 0.2f;
    return o;
}

double target(const scene::Scene& s, const scene::Camera& camera, bool chains,
              const std::vector<light::Vpl>& vpls, size_t* points = nullptr) {
    const trace::Accel accel(s);
    const Importance importance(s, accel, camera, options(chains));
    if (points) *points = importance.point_count();
    return importance.evaluate(vpls);
}

TEST(ImportanceChains, AMirroredViewHasTheTargetOfTheDirectView) {
    light::Vpl vpl;
    vpl.type = light::VplType::Point;
    // Its image in the mirror, (0, −8, −4), lies below the view (57° down from the eye, the
    // view's lowest ray 51°): no glint of the point in the mirror.
    vpl.position = Vec3(0.0f, 8.0f, -4.0f);
    vpl.power = Rgb(10.0f);
    const std::vector<light::Vpl> vpls{vpl};

    const scene::Camera via_mirror =
        scene::look_at_camera(kEye, kTarget, Vec3(0.0f, 1.0f, 0.0f), kYfov, 0.01f);
    // The mirror image of the camera with up mirrored too is a reflection of its frame, which
    // flips the image left to right; the scene and the light are symmetric in x, so the stratum
    // at film (x, y) sees what the mirrored one sees at (W − x, y): the same contribution.
    const Vec3 eye(kEye.x, -kEye.y, kEye.z);
    const scene::Camera direct =
        scene::look_at_camera(eye, kTarget, Vec3(0.0f, -1.0f, 0.0f), kYfov, 0.01f);

    size_t mirrored_points = 0, direct_points = 0;
    const double chained = target(wall_scene(true), via_mirror, true, vpls, &mirrored_points);
    const double expected = target(wall_scene(false), direct, false, vpls, &direct_points);
    const double unchained = target(wall_scene(true), via_mirror, false, vpls);
    ASSERT_GT(direct_points, 200u);  // the wall fills the view
    EXPECT_EQ(mirrored_points, direct_points);
    ASSERT_GT(expected, 0.0);
    // The chain's weight is F·G₂/G₁ = 1 − O(α² tan² θ) with α = 10⁻⁴, and the reflected rays
    // meet the wall at the direct rays' points to float rounding. Its float evaluation is not
    // that exact: D(h) near its peak moves by 2δ/α relative for a half vector rounded by δ
    // (about 10⁻⁷ rad), 2·10⁻³ per point at α = 10⁻⁴, which 256 points average to about 10⁻⁴
    // (measured 0.82·10⁻⁴ under GCC 12, 1.25·10⁻⁴ under clang 14); 4·10⁻⁴ is three times that
    // and far below what a missed point (1/256 of the sum) or a lost bounce weight would change.
    EXPECT_NEAR(chained / expected, 1.0, 4e-4);
    // Without chains the points lie on the mirror, which a point VPL does not light.
    EXPECT_LT(unchained, 1e-3 * expected);
}

}  // namespace
}  // namespace mvpl::sampler
