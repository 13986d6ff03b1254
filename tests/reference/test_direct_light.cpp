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
#include "tests/support/lit_plane.h"
#include "tests/support/scene_builder.h"

namespace mvpl {
namespace {

constexpr int kRes = 24;

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
            const double v = test::lit_plane_radiance(s.lights[0], r.origin + t * r.direction).g;
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
    expect_matches_analytic(test::make_lit_plane(test::example_point_light()));
}

TEST(DirectLight, SpotLight) {
    expect_matches_analytic(test::make_lit_plane(test::example_spot_light()));
}

TEST(DirectLight, DirectionalLight) {
    expect_matches_analytic(test::make_lit_plane(test::example_directional_light()));
}

// Max depth 1 shows emitters only: a scene lit by punctual lights is black.
TEST(DirectLight, DepthOneIsBlackWithoutVisibleEmitters) {
    scene::Light l;
    l.type = scene::LightType::Point;
    l.position = Vec3(0, 1, 0);
    l.intensity = Rgb(1.0f);
    const scene::Scene s = test::make_lit_plane(l);
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
