// What a one-sided face blocks (issue 32, "single-sided occluders"): light paths and shadow rays
// meet both faces of every triangle, whatever glTF's doubleSided says; only camera rays pass
// through the back of a one-sided face (its culling). A floor under a one-sided roof that faces
// the light or away from it, lit by a point light and by a uniform sky (directional VPLs and
// their orthographic maps): the GPU against the CPU oracle over the same VPLs, and the oracle
// against the path tracer.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/core/image_metrics.h"
#include "engine/light/light_sampler.h"
#include "engine/reference/path_tracer.h"
#include "engine/trace/accel.h"
#include "tests/gpu/gpu_test.h"
#include "tests/support/scene_builder.h"
#include "tests/support/vpl_render.h"

namespace mvpl::render {
namespace {

enum class Light { Point, Sky };

// A 4 × 4 floor facing up and a 2 × 4 roof over its −x half at height 1, both one-sided; the
// roof faces up (towards the light) or down. The camera, under the roof's edge, sees only the
// floor: its half under the roof and its half beside it.
scene::Scene roofed_floor(bool roof_faces_up, Light light) {
    scene::Scene s;
    scene::Material m = test::diffuse_material(Rgb(0.6f));
    m.double_sided = false;
    s.materials = {m};
    s.meshes = {test::make_quad(Vec3(-2, 0, -2), Vec3(0, 0, 4), Vec3(4, 0, 0), 0)};
    s.meshes.push_back(roof_faces_up
                           ? test::make_quad(Vec3(-2, 1, -2), Vec3(0, 0, 4), Vec3(2, 0, 0), 0)
                           : test::make_quad(Vec3(-2, 1, -2), Vec3(2, 0, 0), Vec3(0, 0, 4), 0));
    if (light == Light::Point) {
        scene::Light l;
        l.type = scene::LightType::Point;
        l.intensity = Rgb(4.0f);
        l.position = Vec3(-0.5f, 2.0f, 0.0f);
        s.lights = {l};
    } else {
        s.environment.radiance = Rgb(1.0f);
    }
    s.camera = test::look_at(Vec3(0.0f, 0.9f, 0.4f), Vec3(0.0f, 0.0f, 0.0f), 1.0f);
    s.has_camera = true;
    return s;
}

double path_traced_mean(const scene::Scene& s, int res) {
    const trace::Accel accel(s);
    const light::LightSampler lights(s);
    reference::PathTracerOptions o;
    o.width = o.height = res;
    o.spp = 256;
    o.seed = 3;
    o.quiet = true;
    return reference::PathTracer(s, accel, lights).render(o).mean().g;
}

struct OneSidedCase {
    bool roof_faces_up;
    Light light;
};

class OneSidedOccluder : public gpu::testing::GpuTest,
                         public ::testing::WithParamInterface<OneSidedCase> {};

TEST_P(OneSidedOccluder, BlocksAlikeOnTheGpuTheOracleAndThePathTracer) {
    const OneSidedCase c = GetParam();
    const scene::Scene s = roofed_floor(c.roof_faces_up, c.light);
    test::VplRenderSettings settings;
    settings.res = 32;
    settings.clamp = 0.0f;  // unbiased, so that the path tracer's mean is the VPLs' expectation
    // Four independent VPL sets: the spread of their oracle means is the VPLs' noise.
    std::vector<double> means;
    for (uint64_t seed = 1; seed <= 4; ++seed) {
        const light::VplSet vpls = test::monte_carlo_vpls(s, 256, 6, seed);
        const Image oracle = test::oracle_render(s, vpls, settings);
        const ImageError e = compare_images(test::gpu_render(context(), s, vpls, settings), oracle);
        // Same VPLs: only the shadow maps' texel-sized error at the roof's shadow edge differs.
        EXPECT_NEAR(e.mean_ratio.g, 1.0, 0.01) << "seed " << seed;
        EXPECT_LT(e.rel_mse, 0.01) << "seed " << seed;
        means.push_back(oracle.mean().g);
    }
    double mean = 0.0;
    for (const double m : means)
        mean += m / double(means.size());
    double spread = 0.0;
    for (const double m : means)
        spread += (m - mean) * (m - mean) / double(means.size() - 1);
    const double standard_error = std::sqrt(spread / double(means.size()));
    const double traced = path_traced_mean(s, settings.res);
    // Four standard errors of the VPL mean, and 1 % for the path tracer's own noise at 256 spp.
    EXPECT_NEAR(mean / traced, 1.0, 4.0 * standard_error / traced + 0.01)
        << "path tracer " << traced << ", VPLs " << mean << " ± " << standard_error;
    // The roof matters: without it the floor under it is lit.
    scene::Scene open = s;
    open.meshes.pop_back();
    EXPECT_LT(traced, 0.85 * path_traced_mean(open, settings.res));
}

INSTANTIATE_TEST_SUITE_P(RoofAndLight, OneSidedOccluder,
                         ::testing::Values(OneSidedCase{true, Light::Point},
                                           OneSidedCase{false, Light::Point},
                                           OneSidedCase{true, Light::Sky},
                                           OneSidedCase{false, Light::Sky}));

}  // namespace
}  // namespace mvpl::render
