// A point light of intensity I at the centre of a closed Lambertian sphere of albedo a and radius
// R: the radiosity is uniform, B = a·(I/R² + B), so every visible point has
// L = a·I / (π R² (1 − a)). The tessellated sphere's facets are within 0.07% of R (level 5
// icosphere), far below the tolerances.
#include <gtest/gtest.h>

#include "engine/light/light_sampler.h"
#include "engine/reference/path_tracer.h"
#include "engine/trace/accel.h"
#include "tests/support/scene_builder.h"

namespace mvpl {
namespace {

double render_mean(const scene::Scene& s, int spp) {
    const trace::Accel accel(s);
    const light::LightSampler lights(s);
    const reference::PathTracer tracer(s, accel, lights);
    reference::PathTracerOptions o;
    o.width = o.height = 32;
    o.spp = spp;
    o.max_depth = -1;
    o.seed = 11;
    o.quiet = true;
    reference::RenderStats stats;
    const Image image = tracer.render(o, &stats);
    EXPECT_EQ(stats.nonfinite_samples, 0u);
    for (const Rgb& p : image.pixels())
        EXPECT_TRUE(is_finite(p));
    return image.mean().g;
}

struct SphereCase {
    float albedo;
    float tolerance;
    int spp;
};

class IntegratingSphere : public ::testing::TestWithParam<SphereCase> {};

TEST_P(IntegratingSphere, MatchesTheAnalyticRadiance) {
    const SphereCase c = GetParam();
    const float radius = 2.0f, intensity = 5.0f;
    const double expected = c.albedo * intensity / (kPi * radius * radius * (1.0 - c.albedo));
    const double mean =
        render_mean(test::make_integrating_sphere(c.albedo, radius, intensity), c.spp);
    EXPECT_NEAR(mean / expected, 1.0, c.tolerance) << "mean " << mean << " expected " << expected;
}

INSTANTIATE_TEST_SUITE_P(Albedo, IntegratingSphere,
                         ::testing::Values(SphereCase{0.5f, 0.01f, 16},
                                           SphereCase{0.9f, 0.03f, 32}));

}  // namespace
}  // namespace mvpl
