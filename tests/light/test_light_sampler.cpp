// LightSampler against closed forms: selection in proportion to emitted flux, the solid angle
// that sample_li's densities integrate to, one-sided emitters, emission read through the
// material graph (a textured emitter), the point light's emission sample, spot falloff.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "engine/core/rng.h"
#include "engine/light/light_sampler.h"
#include "tests/support/scene_builder.h"

namespace mvpl::light {
namespace {

scene::Light point_light(const Vec3& p, float intensity) {
    scene::Light l;
    l.type = scene::LightType::Point;
    l.position = p;
    l.intensity = Rgb(intensity);
    return l;
}

// A floor and, `height` above the origin, a square emitter of side `side` facing down.
scene::Scene square_light_scene(float side, float height, const Rgb& radiance) {
    scene::Scene s;
    s.materials.push_back(test::diffuse_material(Rgb(0.5f)));
    scene::Material emitter = test::diffuse_material(Rgb(0.0f));
    emitter.emissive = radiance;
    s.materials.push_back(emitter);
    s.meshes.push_back(test::make_quad(Vec3(-2, 0, -2), Vec3(0, 0, 4), Vec3(4, 0, 0), 0));
    const float h = 0.5f * side;
    // cross(a, b) = −Y: the front face looks down at the floor.
    s.meshes.push_back(
        test::make_quad(Vec3(-h, height, -h), Vec3(side, 0, 0), Vec3(0, 0, side), 1));
    return s;
}

TEST(LightSampler, PicksEmittersInProportionToTheirFlux) {
    scene::Scene s;
    s.materials.push_back(test::diffuse_material(Rgb(0.5f)));
    s.meshes.push_back(test::make_quad(Vec3(-1, 0, -1), Vec3(0, 0, 2), Vec3(2, 0, 0), 0));
    s.lights = {point_light(Vec3(0, 1, 0), 1.0f), point_light(Vec3(0, 2, 0), 3.0f)};
    const LightSampler lights(s);
    ASSERT_EQ(lights.emitters().size(), 2u);
    EXPECT_NEAR(lights.pick_probability(0) + lights.pick_probability(1), 1.0f, 1e-6f);
    EXPECT_NEAR(lights.pick_probability(1) / lights.pick_probability(0), 3.0f, 1e-5f);
}

// E[1/pdf] over sample_li's directions is the solid angle the emitter subtends; for a square of
// side a seen on its axis from distance d that is 4·asin(a² / (a² + 4d²)). The tolerance is five
// standard errors of the sample mean, estimated from the samples.
TEST(LightSampler, AreaSamplingDensityIntegratesToTheSolidAngle) {
    const float side = 1.0f, height = 2.0f;
    const scene::Scene s = square_light_scene(side, height, Rgb(1.0f));
    const LightSampler lights(s);
    const Vec3 ref(0.0f, 0.0f, 0.0f);
    Rng rng(5, 0);
    const int n = 200000;
    double sum = 0.0, sum2 = 0.0;
    for (int i = 0; i < n; ++i) {
        const std::optional<LightSample> ls =
            lights.sample_li(ref, rng.next_float(), Vec2(rng.next_float(), rng.next_float()));
        ASSERT_TRUE(ls);
        ASSERT_GT(ls->pdf, 0.0f);
        const int triangle = ls->p.x > ls->p.z ? 0 : 1;  // either: both have the same area
        EXPECT_NEAR(lights.pdf_li(ref, 1, triangle, ls->p, ls->n), ls->pdf, 1e-4f * ls->pdf);
        const double w = 1.0 / double(ls->pdf);
        sum += w;
        sum2 += w * w;
    }
    const double mean = sum / n;
    const double se = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
    const double a2 = double(side) * side;
    const double omega = 4.0 * std::asin(a2 / (a2 + 4.0 * double(height) * height));
    EXPECT_NEAR(mean, omega, 5.0 * se + 1e-9);
}

TEST(LightSampler, EmittersShineFromTheirFrontFaceOnly) {
    const scene::Scene s = square_light_scene(1.0f, 2.0f, Rgb(2.0f, 1.0f, 0.5f));
    const LightSampler lights(s);
    const Vec2 b(0.25f, 0.25f);
    const Rgb down = lights.emitted_radiance(1, 0, b, Vec3(0, -1, 0));
    EXPECT_EQ(down, Rgb(2.0f, 1.0f, 0.5f));
    EXPECT_EQ(lights.emitted_radiance(1, 0, b, Vec3(0, 1, 0)), Rgb(0.0f));
}

// The emitted radiance is the material graph's: emissive · strength · texel.
TEST(LightSampler, TexturedEmitterReadsItsEmissionGraph) {
    scene::Scene s = square_light_scene(1.0f, 2.0f, Rgb(2.0f));
    s.materials[1].emissive_strength = 3.0f;
    s.materials[1].emissive_texture.texture = 0;
    scene::Texture t;
    t.width = t.height = 1;
    t.texels = {Vec4(0.5f, 1.0f, 0.25f, 1.0f)};
    s.textures.push_back(t);
    const LightSampler lights(s);
    const Rgb l = lights.emitted_radiance(1, 1, Vec2(0.3f, 0.3f), Vec3(0, -1, 0));
    EXPECT_NEAR(l.r, 3.0f, 1e-5f);
    EXPECT_NEAR(l.g, 6.0f, 1e-5f);
    EXPECT_NEAR(l.b, 1.5f, 1e-5f);
}

// A point light's emission sample: uniform over the sphere (pdf 1/4π), throughput
// I / (pick · pdf_dir) = 4π I, and the emitter VPL's le = I / pick.
TEST(LightSampler, PointLightEmissionSample) {
    scene::Scene s;
    s.materials.push_back(test::diffuse_material(Rgb(0.5f)));
    s.meshes.push_back(test::make_quad(Vec3(-1, 0, -1), Vec3(0, 0, 2), Vec3(2, 0, 0), 0));
    s.lights = {point_light(Vec3(0, 1, 0), 2.0f)};
    const LightSampler lights(s);
    const std::optional<EmissionSample> e = lights.sample_le(0.5f, Vec2(0.3f), Vec2(0.2f, 0.7f));
    ASSERT_TRUE(e);
    EXPECT_EQ(e->type, EmitterType::Point);
    EXPECT_NEAR(e->pick, 1.0f, 1e-6f);
    EXPECT_NEAR(e->pdf_dir, 1.0f / (4.0f * kPi), 1e-6f);
    EXPECT_NEAR(glm::length(e->direction), 1.0f, 1e-5f);
    EXPECT_NEAR(e->throughput.r, 4.0f * kPi * 2.0f, 1e-4f);
    EXPECT_NEAR(e->le.r, 2.0f, 1e-6f);
    EXPECT_EQ(e->p, Vec3(0, 1, 0));
}

// KHR_lights_punctual: 1 inside the inner cone, 0 outside the outer, smooth and monotone between.
// An emitter whose power overflows float must not be left out silently (the scene would render
// black with exit code 0): the loaders refuse such scenes (scene::check_emitted_power), and a
// scene built around them is a bug the sampler reports.
TEST(LightSampler, PowerBeyondFloatIsAnErrorNotADroppedLight) {
    scene::Scene s;
    s.materials.push_back(test::diffuse_material(Rgb(0.5f)));
    s.meshes.push_back(test::make_quad(Vec3(-1, 0, -1), Vec3(0, 0, 2), Vec3(2, 0, 0), 0));
    s.lights = {point_light(Vec3(0, 1, 0), 1e38f)};  // 4π · 1e38 > FLT_MAX
    EXPECT_THROW(LightSampler{s}, std::logic_error);
    s.lights = {point_light(Vec3(0, 1, 0), 2e37f)};  // 2.5e38 fits, barely
    const LightSampler lights(s);
    ASSERT_EQ(lights.emitters().size(), 1u);
    EXPECT_GT(lights.total_power(), 2e38f);
}

TEST(SpotAttenuation, FullInsideZeroOutsideMonotoneBetween) {
    scene::Light spot;
    spot.type = scene::LightType::Spot;
    spot.inner_cone = 0.2f;
    spot.outer_cone = 0.5f;
    EXPECT_FLOAT_EQ(spot_attenuation(spot, std::cos(0.1f)), 1.0f);
    EXPECT_FLOAT_EQ(spot_attenuation(spot, std::cos(0.6f)), 0.0f);
    float previous = 1.0f;
    for (float angle = 0.2f; angle <= 0.5f; angle += 0.01f) {
        const float a = spot_attenuation(spot, std::cos(angle));
        EXPECT_LE(a, previous + 1e-6f) << angle;
        EXPECT_GE(a, 0.0f);
        previous = a;
    }
}

}  // namespace
}  // namespace mvpl::light
