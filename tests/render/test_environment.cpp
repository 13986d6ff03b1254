// A uniform environment (issue 12: a default sky for scenes without light), against closed forms:
// a diffuse plane of albedo a under a sky of radiance L has radiance a·L (it sees the sky over
// its whole upper hemisphere, irradiance π L); so does every point of a convex diffuse body,
// which cannot see itself. The path tracer (escaped rays, and next-event estimation of the sky
// with MIS) and the GPU VPL renderer (the sky's direct light as directional VPLs) both.
#include <gtest/gtest.h>

#include "engine/core/image.h"
#include "engine/light/light_sampler.h"
#include "engine/reference/path_tracer.h"
#include "engine/render/vpl_renderer.h"
#include "engine/sampler/monte_carlo_sampler.h"
#include "engine/trace/accel.h"
#include "tests/gpu/gpu_test.h"
#include "tests/support/scene_builder.h"

namespace mvpl::render {
namespace {

using EnvironmentTest = gpu::testing::GpuTest;

const Rgb kSky(0.8f, 1.0f, 1.3f);
constexpr int kSize = 32;

// A 2 m × 2 m diffuse plane (front face up) seen from 1 m straight above: it fills the view.
scene::Scene plane_under_sky(float albedo) {
    scene::Scene s;
    s.materials = {test::diffuse_material(Rgb(albedo))};
    s.meshes.push_back(test::make_quad(Vec3(-1, 0, -1), Vec3(0, 0, 2), Vec3(2, 0, 0), 0));
    s.camera = test::look_at(Vec3(0.0f, 1.0f, 0.01f), Vec3(0, 0, 0), 0.8f);
    s.has_camera = true;
    s.environment.radiance = kSky;
    return s;
}

// A diffuse sphere of radius 0.5 (level-3 icosphere, flat facets, outward) seen from 3 m with a
// field of view narrower than its silhouette: it fills the view.
scene::Scene sphere_under_sky(float albedo) {
    scene::Scene s;
    s.materials = {test::diffuse_material(Rgb(albedo))};
    s.meshes.push_back(test::make_icosphere(Vec3(0.0f), 0.5f, 3, false, 0));
    s.camera = test::look_at(Vec3(0.0f, 0.3f, 3.0f), Vec3(0, 0, 0), 0.25f);
    s.has_camera = true;
    s.environment.radiance = kSky;
    return s;
}

Image path_traced(const scene::Scene& s, int max_depth, int spp) {
    const trace::Accel accel(s);
    const light::LightSampler lights(s);
    reference::PathTracerOptions o;
    o.width = o.height = kSize;
    o.spp = spp;
    o.max_depth = max_depth;
    o.quiet = true;
    return reference::PathTracer(s, accel, lights).render(o);
}

// Halton light paths (the sky's directions low-discrepancy), shaded on the GPU.
Image vpl_rendered(gpu::Context& context, const scene::Scene& s, int max_depth, uint64_t paths) {
    const trace::Accel accel(s);
    const light::LightSampler lights(s);
    sampler::MonteCarloOptions mc;
    mc.paths = paths;
    mc.qmc = true;
    mc.tracer.max_depth = max_depth;
    const light::VplSet vpls = sampler::MonteCarloSampler(s, accel, lights).generate(mc);
    RenderOptions o;
    o.width = o.height = kSize;
    o.clamp = 0.0f;
    VplRenderer renderer(context, s);
    return renderer.render(vpls, o);
}

void expect_mean_near(const Image& image, const Rgb& expected, float tolerance, const char* what) {
    const Rgb mean = image.mean();
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(mean[c] / expected[c], 1.0f, tolerance) << what << ", channel " << c;
    }
    ::testing::Test::RecordProperty(std::string(what) + "_ratio_g",
                                    std::to_string(mean.g / expected.g));
}

TEST(EnvironmentPathTracer, PlaneAndConvexSphereReflectAlbedoTimesSky) {
    // 256 spp × 1024 pixels: the 0.5 % (measured: 1.0003 of a·L; 0.9998 of L below).
    expect_mean_near(path_traced(plane_under_sky(0.5f), 2, 256), 0.5f * kSky, 0.005f, "plane");
    // Albedo 1, unlimited depth: nothing to bounce between on a convex body, and nothing may
    // blow up either.
    expect_mean_near(path_traced(sphere_under_sky(1.0f), -1, 256), kSky, 0.01f, "sphere");
    // Rays that leave the scene see the sky, and only it: a camera looking away from the plane.
    scene::Scene up = plane_under_sky(0.5f);
    up.camera = test::look_at(Vec3(0.0f, 1.0f, 0.0f), Vec3(0.0f, 2.0f, 0.01f), 0.8f);
    const Image sky = path_traced(up, 2, 1);
    for (const Rgb& p : sky.pixels())
        ASSERT_EQ(p, kSky);
}

TEST_F(EnvironmentTest, VplRendererMatchesTheClosedForm) {
    // 1024 Halton directions of the sky, each a directional VPL with its own orthographic shadow
    // map: the 1 % (measured: 0.996 of a·L on the plane, 0.999 of L on the sphere).
    expect_mean_near(vpl_rendered(context(), plane_under_sky(0.5f), 2, 1024), 0.5f * kSky, 0.01f,
                     "plane");
    expect_mean_near(vpl_rendered(context(), sphere_under_sky(1.0f), -1, 1024), kSky, 0.01f,
                     "sphere");
    scene::Scene up = plane_under_sky(0.5f);
    up.camera = test::look_at(Vec3(0.0f, 1.0f, 0.0f), Vec3(0.0f, 2.0f, 0.01f), 0.8f);
    const Image sky = vpl_rendered(context(), up, 2, 16);
    for (const Rgb& p : sky.pixels())
        ASSERT_EQ(p, kSky);  // the G-buffer's background holds the sky, once
}

}  // namespace
}  // namespace mvpl::render
