// Direct light from punctual lights on a Lambertian plane, at max depth 2, against the analytic
// answer L = ρ/π · E, with E = I·cos θ / d² (point, spot with the KHR_lights_punctual falloff) or
// E = E⊥·cos θ (directional). The expected pixel value integrates the analytic radiance over the
// pixel footprint (the tracer's box filter) on an 8×8 grid. The light is a delta, so the only
// randomness is where the 64 jittered samples fall in the pixel: the standard error is the spread
// σ of the radiance over the footprint divided by √64, and each pixel must lie within 5 of those
// (plus 0.5% for the grid quadrature).
#include <gtest/gtest.h>

#include "engine/light/light_sampler.h"
#include "engine/reference/path_tracer.h"
#include "engine/scene/camera.h"
#include "engine/trace/accel.h"
#include "tests/support/scene_builder.h"

namespace mvpl {
namespace {

constexpr float kAlbedo = 0.6f;
constexpr int kRes = 24;

scene::Scene lit_plane(const scene::Light& light) {
    scene::Scene s;
    s.materials.push_back(test::diffuse_material(Rgb(kAlbedo)));
    s.meshes.push_back(test::make_quad(Vec3(-2, 0, -2), Vec3(0, 0, 4), Vec3(4, 0, 0), 0));
    s.lights.push_back(light);
    s.camera = test::look_at(Vec3(0.3f, 3.0f, 0.2f), Vec3(0.3f, 0.0f, 0.0f), 0.9f);
    s.has_camera = true;
    return s;
}

Rgb analytic_radiance(const scene::Light& light, const Vec3& p) {
    const Vec3 n(0, 1, 0);
    if (light.type == scene::LightType::Directional) {
        return kAlbedo * kInvPi * light.intensity * std::max(0.0f, glm::dot(n, -light.direction));
    }
    const Vec3 d = light.position - p;
    const float dist2 = glm::dot(d, d);
    const Vec3 wi = d / std::sqrt(dist2);
    float falloff = 1.0f;
    if (light.type == scene::LightType::Spot) {
        // KHR_lights_punctual's reference falloff, written out independently of the renderer.
        const float scale =
            1.0f / std::max(0.001f, std::cos(light.inner_cone) - std::cos(light.outer_cone));
        const float offset = -std::cos(light.outer_cone) * scale;
        const float a = std::clamp(glm::dot(light.direction, -wi) * scale + offset, 0.0f, 1.0f);
        falloff = a * a;
    }
    return kAlbedo * kInvPi * light.intensity * falloff * std::max(0.0f, glm::dot(n, wi)) / dist2;
}

struct PixelExpectation {
    float mean = 0.0f;    // green channel
    float spread = 0.0f;  // standard deviation over the footprint
};

PixelExpectation expected_pixel(const scene::Scene& s, int x, int y) {
    constexpr int kGrid = 8;
    double sum = 0.0, sum2 = 0.0;
    for (int j = 0; j < kGrid; ++j) {
        for (int i = 0; i < kGrid; ++i) {
            const Vec2 film(x + (i + 0.5f) / kGrid, y + (j + 0.5f) / kGrid);
            const scene::CameraRay r = scene::generate_camera_ray(s.camera, kRes, kRes, film);
            const float t = -r.origin.y / r.direction.y;
            const double v = analytic_radiance(s.lights[0], r.origin + t * r.direction).g;
            sum += v;
            sum2 += v * v;
        }
    }
    const double n = kGrid * kGrid;
    const double mean = sum / n;
    return {float(mean), float(std::sqrt(std::max(0.0, sum2 / n - mean * mean)))};
}

void expect_matches_analytic(const scene::Scene& s) {
    const trace::Accel accel(s);
    const light::LightSampler lights(s);
    const reference::PathTracer tracer(s, accel, lights);
    reference::PathTracerOptions o;
    o.width = o.height = kRes;
    o.spp = 64;
    o.max_depth = 2;
    o.quiet = true;
    const Image image = tracer.render(o);
    int outside = 0;
    double lit = 0.0;
    for (int y = 0; y < kRes; ++y) {
        for (int x = 0; x < kRes; ++x) {
            const PixelExpectation e = expected_pixel(s, x, y);
            const float got = image.at(x, y).g;
            const float tolerance =
                5.0f * e.spread / std::sqrt(float(o.spp)) + 5e-3f * e.mean + 1e-7f;
            if (std::abs(got - e.mean) > tolerance) {
                ++outside;
                ADD_FAILURE() << "pixel " << x << "," << y << ": " << got << " expected " << e.mean
                              << " ± " << tolerance;
            }
            lit += e.mean;
        }
    }
    EXPECT_EQ(outside, 0);
    EXPECT_GT(lit,
              0.0);  // the light reaches the plane: the comparison is not between two black images
}

TEST(DirectLight, PointLight) {
    scene::Light l;
    l.type = scene::LightType::Point;
    l.position = Vec3(-0.4f, 1.2f, 0.3f);
    l.intensity = Rgb(3.0f, 2.0f, 1.0f);
    expect_matches_analytic(lit_plane(l));
}

TEST(DirectLight, SpotLight) {
    scene::Light l;
    l.type = scene::LightType::Spot;
    l.position = Vec3(0.3f, 1.0f, 0.0f);
    l.direction = glm::normalize(Vec3(0.2f, -1.0f, 0.1f));
    l.inner_cone = 0.3f;
    l.outer_cone = 0.6f;
    l.intensity = Rgb(4.0f);
    expect_matches_analytic(lit_plane(l));
}

TEST(DirectLight, DirectionalLight) {
    scene::Light l;
    l.type = scene::LightType::Directional;
    l.direction = glm::normalize(Vec3(0.5f, -1.0f, 0.25f));
    l.intensity = Rgb(2.0f);
    expect_matches_analytic(lit_plane(l));
}

// Max depth 1 shows emitters only: a scene lit by punctual lights is black.
TEST(DirectLight, DepthOneIsBlackWithoutVisibleEmitters) {
    scene::Light l;
    l.type = scene::LightType::Point;
    l.position = Vec3(0, 1, 0);
    l.intensity = Rgb(1.0f);
    const scene::Scene s = lit_plane(l);
    const trace::Accel accel(s);
    const light::LightSampler lights(s);
    reference::PathTracerOptions o;
    o.width = o.height = 8;
    o.spp = 4;
    o.max_depth = 1;
    o.quiet = true;
    EXPECT_EQ(reference::PathTracer(s, accel, lights).render(o).mean(), Rgb(0.0f));
}

}  // namespace
}  // namespace mvpl
