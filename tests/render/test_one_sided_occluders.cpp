// What a one-sided face blocks (issue 32, "single-sided occluders"): light paths and shadow rays
// meet both faces of every triangle, whatever glTF's doubleSided says; only camera rays pass
// through the back of a one-sided face (its culling). A floor under a one-sided roof that faces
// the light or away from it, lit by a point light and by a uniform sky (directional VPLs and
// their orthographic maps): the GPU against the CPU oracle over the same VPLs, and the oracle
// against the path tracer; and a closed room of one-sided walls that must let nothing in.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "engine/core/image_metrics.h"
#include "engine/light/light_sampler.h"
#include "engine/reference/path_tracer.h"
#include "engine/trace/accel.h"
#include "tests/gpu/gpu_test.h"
#include "tests/render/render_test_util.h"
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

// A closed room of six one-sided walls facing in, each cut into divisions² quads, lit from
// outside by the sky (directional VPLs, orthographic maps) or a point light (cubes); the camera
// inside looks into a corner. Nothing enters, so every pixel is 0 on the oracle and must be on
// the GPU, wherever the room's edges fall against the maps' texels: the room's sides, scale,
// tessellation and the maps' resolution move them.
struct ClosedRoomCase {
    Vec3 size;
    float scale;
    int divisions;
    int shadow_res;
    Light light;
};

scene::Scene closed_room(const ClosedRoomCase& c, bool with_ceiling) {
    scene::Scene s;
    scene::Material m = test::diffuse_material(Rgb(0.6f));
    m.double_sided = false;
    s.materials = {m};
    const Vec3 lo = -0.5f * c.size;
    const Vec3 x(c.size.x, 0, 0), y(0, c.size.y, 0), z(0, 0, c.size.z);
    // Corner and sides of each wall, cross(a, b) pointing into the room.
    const struct {
        Vec3 p, a, b;
    } walls[] = {{lo, z, x},     {lo + y, x, z}, {lo, y, z},
                 {lo + x, z, y}, {lo, x, y},     {lo + z, y, x}};
    const float step = 1.0f / float(c.divisions);
    for (const auto& w : walls) {
        if (!with_ceiling && w.p == lo + y) continue;
        for (int i = 0; i < c.divisions; ++i)
            for (int j = 0; j < c.divisions; ++j)
                s.meshes.push_back(
                    test::make_quad(w.p + w.a * (step * float(i)) + w.b * (step * float(j)),
                                    w.a * step, w.b * step, 0));
    }
    if (c.light == Light::Point) {
        scene::Light l;
        l.type = scene::LightType::Point;
        l.intensity = Rgb(40.0f);
        l.position = Vec3(0.9f * c.size.x, 0.8f * c.size.y, 0.7f * c.size.z);
        s.lights = {l};
    } else {
        s.environment.radiance = Rgb(1.0f);
    }
    s.camera = test::look_at(Vec3(0.2f * c.size.x, 0.1f * c.size.y, 0.3f * c.size.z),
                             lo + Vec3(0.05f * c.size.x, 0.0f, 0.0f), 1.5f);
    s.has_camera = true;
    test::scale_scene(s, c.scale);
    return s;
}

class ClosedRoom : public gpu::testing::GpuTest,
                   public ::testing::WithParamInterface<ClosedRoomCase> {};

// The thin-wall method's junction band (test_thin_walls.cpp, junction_band): a receiver closer
// than 0.75 texel footprints to another wall's plane may see light past that wall's edge, where
// the two planes meet within a texel. The footprint is the orthographic maps' texel (their window
// is at most 1.02 scene diagonals wide: directional_frame.cpp) or a cube texel's 2/res at the
// receiver's distance from the point light.
bool in_junction_band(const ClosedRoomCase& c, const scene::Scene& room, const Vec3& p) {
    const float footprint =
        c.light == Light::Sky
            ? 1.02f * glm::length(c.scale * c.size) / float(c.shadow_res)
            : glm::length(p - room.lights[0].position) * 2.0f / float(c.shadow_res);
    const Vec3 half = 0.5f * c.scale * c.size;
    std::vector<float> distances;
    for (int axis = 0; axis < 3; ++axis) {
        distances.push_back(std::abs(p[axis] - half[axis]));
        distances.push_back(std::abs(p[axis] + half[axis]));
    }
    std::sort(distances.begin(), distances.end());
    return distances[1] < 0.75f * footprint;  // distances[0]: the receiver's own wall
}

TEST_P(ClosedRoom, LetsNoLightInOutsideTheJunctionBand) {
    const ClosedRoomCase c = GetParam();
    test::VplRenderSettings settings;
    settings.res = 32;
    settings.shadow_res = c.shadow_res;
    settings.clamp = 0.0f;
    settings.jitter = false;  // pixel centres, where cast_camera_ray finds the receivers
    const scene::Scene room = closed_room(c, true);
    const light::VplSet vpls = test::monte_carlo_vpls(room, 256, 6, 5);
    const Image gpu = test::gpu_render(context(), room, vpls, settings);
    EXPECT_EQ(test::oracle_render(room, vpls, settings).mean().g, 0.0);
    for (int y = 0; y < settings.res; ++y) {
        for (int x = 0; x < settings.res; ++x) {
            const auto hit = testing::cast_camera_ray(room, settings.res, settings.res, x, y);
            ASSERT_TRUE(hit.has_value());
            if (in_junction_band(c, room, hit->p)) continue;
            EXPECT_EQ(gpu.at(x, y).g, 0.0f) << "pixel " << x << "," << y << " at (" << hit->p.x
                                            << ", " << hit->p.y << ", " << hit->p.z << ")";
        }
    }
    // Without its ceiling the same room is lit: the zeros above are the walls' doing.
    const scene::Scene open = closed_room(c, false);
    EXPECT_GT(test::gpu_render(context(), open, test::monte_carlo_vpls(open, 256, 6, 5), settings)
                  .mean()
                  .g,
              0.01);
}

INSTANTIATE_TEST_SUITE_P(
    SidesScalesAndMaps, ClosedRoom,
    ::testing::Values(ClosedRoomCase{Vec3(4.0f), 1.0f, 1, 128, Light::Sky},
                      ClosedRoomCase{Vec3(4.0f, 3.7f, 4.3f), 1e-3f, 3, 128, Light::Sky},
                      ClosedRoomCase{Vec3(4.1f, 4.0f, 3.9f), 1e3f, 1, 64, Light::Sky},
                      ClosedRoomCase{Vec3(3.3f, 2.9f, 5.1f), 1.0f, 2, 256, Light::Sky},
                      ClosedRoomCase{Vec3(4.0f), 1.0f, 1, 128, Light::Point},
                      ClosedRoomCase{Vec3(3.3f, 2.9f, 5.1f), 1e-3f, 2, 64, Light::Point}),
    [](const ::testing::TestParamInfo<ClosedRoomCase>& info) {
        const ClosedRoomCase& c = info.param;
        return std::string(c.light == Light::Sky ? "Sky" : "Point") + "_" +
               std::to_string(info.index) + "_Map" + std::to_string(c.shadow_res) + "_Div" +
               std::to_string(c.divisions);
    });

}  // namespace
}  // namespace mvpl::render
