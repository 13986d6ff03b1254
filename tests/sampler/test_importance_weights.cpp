// The relative target's point weights and the share of its mass given back to plain luminance
// (ImportanceOptions::absolute_share): point k's share of the target's mass, w_k·L_k / Σ w·L, is
// (1 − s) × its share under the relative weights + s × its share of the plain luminance, L_k / Σ L.
#include <gtest/gtest.h>

#include <vector>

#include "engine/sampler/importance.h"
#include "engine/scene/camera.h"
#include "engine/trace/accel.h"
#include "tests/support/scene_builder.h"

namespace mvpl::sampler {
namespace {

// Point k's share of the target's mass for radiance L (unit luminance at one point at a time
// reads w_k / rays off evaluate()).
std::vector<double> mass_shares(double share, const std::vector<double>& radiance) {
    scene::Scene s;
    s.materials.push_back(test::diffuse_material(Rgb(0.8f)));
    s.meshes.push_back(test::make_quad(Vec3(-12.0f, -12.0f, -8.0f), Vec3(24.0f, 0.0f, 0.0f),
                                       Vec3(0.0f, 24.0f, 0.0f), 0));
    const trace::Accel accel(s);
    const scene::Camera camera = scene::look_at_camera(Vec3(0.0f), Vec3(0.0f, 0.0f, -1.0f),
                                                       Vec3(0.0f, 1.0f, 0.0f), 0.5f, 0.01f);
    ImportanceOptions o;
    o.points = 16;
    o.width = o.height = 16;
    o.absolute_share = share;
    Importance importance(s, accel, camera, o);
    EXPECT_EQ(importance.point_count(), radiance.size());  // the wall fills the view
    importance.set_point_radiance(radiance);
    std::vector<double> mass(radiance.size());
    double sum = 0.0;
    for (size_t k = 0; k < radiance.size(); ++k) {
        std::vector<float> unit(radiance.size(), 0.0f);
        unit[k] = 1.0f;
        mass[k] = importance.evaluate(std::span<const float>(unit)) * radiance[k];
        sum += mass[k];
    }
    for (double& m : mass)
        m /= sum;
    return mass;
}

TEST(ImportanceWeights, TheAbsoluteShareMixesTheMassesInProportion) {
    // One bright point (the room seen through an opening) among dim ones.
    std::vector<double> radiance(16, 0.05);
    radiance[5] = 15.0;
    double total = 0.0;
    for (double l : radiance)
        total += l;
    const std::vector<double> relative = mass_shares(0.0, radiance);
    const std::vector<double> plain = mass_shares(1.0, radiance);
    const std::vector<double> half = mass_shares(0.5, radiance);
    // Relative weights: the bright point gets little of the mass however bright it is.
    EXPECT_LT(relative[5], 0.2);
    for (size_t k = 0; k < radiance.size(); ++k) {
        EXPECT_NEAR(plain[k], radiance[k] / total, 1e-9) << "point " << k;
        EXPECT_NEAR(half[k], 0.5 * relative[k] + 0.5 * radiance[k] / total, 1e-9) << "point " << k;
    }
}

}  // namespace
}  // namespace mvpl::sampler
