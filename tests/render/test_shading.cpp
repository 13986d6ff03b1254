#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "engine/core/image.h"
#include "engine/core/subpixel.h"
#include "engine/gpu/context.h"
#include "engine/render/vpl_renderer.h"
#include "tests/gpu/gpu_test.h"
#include "tests/render/render_test_util.h"
#include "tests/support/scene_builder.h"

namespace mvpl::render {
namespace {

using ShadingTest = gpu::testing::GpuTest;

constexpr int kShadingSize = 48;

scene::Scene floor_scene(const scene::Material& material) {
    scene::Scene s;
    s.materials = {material};
    s.meshes.push_back(test::make_quad(Vec3(-2, 0, -2), Vec3(0, 0, 4), Vec3(4, 0, 0), 0));
    s.camera = test::look_at(Vec3(0.3f, 2.0f, 2.5f), Vec3(0, 0, -0.2f), 0.9f);
    s.has_camera = true;
    return s;
}

float relative_error(const Rgb& got, const Rgb& want) {
    const float scale = std::max(max_component(want), 1e-30f);
    return max_component(glm::abs(got - want)) / scale;
}

TEST_F(ShadingTest, APointVplOverADiffusePlaneGivesTheAnalyticDirectLight) {
    const Rgb albedo(0.3f, 0.6f, 0.9f);
    const scene::Scene scene = floor_scene(test::diffuse_material(albedo));
    light::Vpl vpl;
    vpl.type = light::VplType::Point;
    vpl.position = Vec3(0.4f, 1.2f, -0.3f);
    vpl.power = Rgb(5.0f, 4.0f, 3.0f);

    VplRenderer renderer(context(), scene);
    RenderOptions options;
    options.width = options.height = kShadingSize;
    options.shadow_resolution = 32;
    options.batch = 4;
    options.clamp = 0.0f;
    const Image image = renderer.render({{vpl}}, options);

    int lit = 0;
    float worst = 0.0f;
    for (int y = 0; y < kShadingSize; ++y) {
        for (int x = 0; x < kShadingSize; ++x) {
            const std::optional<testing::CpuHit> hit =
                testing::cast_camera_ray(scene, kShadingSize, kShadingSize, x, y);
            if (!hit) {
                EXPECT_EQ(image.at(x, y), Rgb(0.0f));
                continue;
            }
            // E = I cos θ / d², L = ρ/π · E (the plane's normal is +y).
            const Vec3 to_light = vpl.position - hit->p;
            const float d2 = glm::dot(to_light, to_light);
            const float cos_theta = to_light.y / std::sqrt(d2);
            const Rgb expected = albedo * kInvPi * vpl.power * cos_theta / d2;
            ++lit;
            worst = std::max(worst, relative_error(image.at(x, y), expected));
        }
    }
    EXPECT_GT(lit, kShadingSize * kShadingSize / 2);
    EXPECT_LT(worst, 1e-3f);
    RecordProperty("worst_relative_error", std::to_string(worst));
}

// A glossy surface VPL, an area, a spot and a directional VPL above floor_scene's plane.
std::vector<light::Vpl> mixed_vpls() {
    std::vector<light::Vpl> vpls(4);
    light::Vpl& surface = vpls[0];
    surface.type = light::VplType::Surface;
    surface.position = Vec3(-0.5f, 0.8f, -0.6f);
    surface.normal = glm::normalize(Vec3(0.3f, -1.0f, 0.4f));
    surface.shading_normal = glm::normalize(Vec3(0.35f, -1.0f, 0.3f));
    surface.wi = glm::normalize(Vec3(-0.4f, -0.5f, -0.2f));
    surface.power = Rgb(1.5f, 1.2f, 1.0f);
    surface.closure.base_color = Rgb(0.2f, 0.8f, 0.4f);
    surface.closure.metallic = 0.6f;
    surface.closure.roughness = 0.3f;
    surface.closure.specular = 1.0f;
    surface.closure.specular_color = Rgb(1.0f);
    surface.closure.ior = 1.45f;
    surface.path_length = 1;
    light::Vpl& area = vpls[1];
    area.type = light::VplType::Area;
    area.position = Vec3(0.6f, 1.1f, 0.2f);
    area.normal = glm::normalize(Vec3(-0.2f, -1.0f, -0.1f));
    area.power = Rgb(2.0f, 2.5f, 3.0f);
    light::Vpl& spot = vpls[2];
    spot.type = light::VplType::Spot;
    spot.position = Vec3(0.0f, 1.5f, 0.5f);
    spot.normal = glm::normalize(Vec3(0.1f, -1.0f, -0.3f));
    spot.cos_inner = std::cos(0.3f);
    spot.cos_outer = std::cos(0.6f);
    spot.power = Rgb(3.0f);
    light::Vpl& directional = vpls[3];
    directional.type = light::VplType::Directional;
    directional.normal = glm::normalize(Vec3(0.5f, -1.0f, 0.2f));
    directional.power = Rgb(0.3f, 0.2f, 0.1f);
    return vpls;
}

TEST_F(ShadingTest, GlossySurfaceAreaSpotAndDirectionalVplsMatchTheCpuFormulas) {
    scene::Material glossy;
    glossy.base_color = Rgb(0.7f, 0.5f, 0.3f);
    glossy.metallic = 0.3f;
    glossy.roughness = 0.35f;
    glossy.specular = 0.8f;
    glossy.specular_color = Rgb(1.0f, 0.9f, 0.95f);
    glossy.ior = 1.6f;
    const scene::Scene scene = floor_scene(glossy);

    const std::vector<light::Vpl> vpls = mixed_vpls();

    VplRenderer renderer(context(), scene);
    RenderOptions options;
    options.width = options.height = kShadingSize;
    options.shadow_resolution = 32;
    options.batch = 3;      // two batches: accumulation across batches is part of the test
    options.clamp = 0.05f;  // d_min = 0.05 · diagonal ≈ 0.28: active for the nearby pixels
    // Virtual spherical lights of radius 0.1 · diagonal ≈ 0.57, comparable to the VPLs' heights:
    // the surface and area VPLs' lobes are widened for every pixel.
    options.vsl_radius = 0.1f;
    const Image image = renderer.render({vpls}, options);

    // Each batch at its own sub-pixel position: the CPU formulas at the same positions.
    const SubpixelSchedule schedule = subpixel_schedule(options);
    ASSERT_NE(schedule.position_of(0), schedule.position_of(3)) << "the batches are jittered";
    const float d_min = options.clamp * std::sqrt(32.0f);  // the floor's diagonal
    const float vsl_radius = options.vsl_radius * std::sqrt(32.0f);
    const material::ClosureParams receiver = testing::closure_of(glossy);
    int compared = 0;
    int lit = 0;
    float worst = 0.0f;
    for (int y = 0; y < kShadingSize; ++y) {
        for (int x = 0; x < kShadingSize; ++x) {
            if (!testing::cast_camera_ray(scene, kShadingSize, kShadingSize, x, y)) continue;
            Rgb expected(0.0f);
            for (size_t i = 0; i < vpls.size(); ++i) {
                const Vec2 at = schedule.position(schedule.position_of(i));
                const std::optional<testing::CpuHit> hit =
                    testing::cast_camera_ray(scene, kShadingSize, kShadingSize, x, y, at);
                if (!hit) continue;
                expected += testing::cpu_contribution(vpls[i], hit->p, hit->ng, receiver,
                                                      scene.camera.position(), d_min, vsl_radius);
            }
            ++compared;
            if (max_component(expected) > 1e-4f) ++lit;
            worst = std::max(worst, relative_error(image.at(x, y), expected));
        }
    }
    EXPECT_GT(compared, kShadingSize * kShadingSize / 2);
    EXPECT_GT(lit, compared * 9 / 10) << "the comparison must not be of zeros";
    EXPECT_LT(worst, 1e-3f);
    RecordProperty("worst_relative_error", std::to_string(worst));
}

// Issue 15, item 2: VSL pairs closer than d_min are clamped lobe by lobe. A glossy plastic floor
// under a glossy surface VPL and an area VPL 0.08–0.1 above it, d_min = 0.2 · diagonal ≈ 1.13
// and spheres of r = 0.01 · diagonal ≈ 0.057: every pixel's pair is closer than d_min, so only
// its diffuse × diffuse product is clamped, its glossy products are divided by max(d², r²). The
// GPU must give the CPU formula (render_test_util.h, written out from vpl.h) to 1e-3, as the
// test above; and the formula must differ from clamping everything, or the test could not fail.
TEST_F(ShadingTest, CloseGlossyPairsAreClampedOnlyInTheirDiffuseProduct) {
    scene::Material glossy;
    glossy.base_color = Rgb(0.6f, 0.5f, 0.4f);
    glossy.metallic = 0.0f;
    glossy.roughness = 0.3f;
    glossy.specular = 1.0f;
    const scene::Scene scene = floor_scene(glossy);

    std::vector<light::Vpl> vpls(2);
    light::Vpl& surface = vpls[0];
    surface.type = light::VplType::Surface;
    surface.position = Vec3(0.1f, 0.08f, 0.2f);
    surface.normal = glm::normalize(Vec3(0.1f, -1.0f, 0.2f));
    surface.shading_normal = surface.normal;
    surface.wi = glm::normalize(Vec3(-0.3f, -0.6f, 0.5f));
    surface.power = Rgb(0.02f, 0.015f, 0.01f);
    surface.closure.base_color = Rgb(0.3f, 0.7f, 0.5f);
    surface.closure.metallic = 0.4f;
    surface.closure.roughness = 0.25f;
    surface.closure.specular = 1.0f;
    surface.path_length = 1;
    light::Vpl& area = vpls[1];
    area.type = light::VplType::Area;
    area.position = Vec3(-0.3f, 0.1f, -0.4f);
    area.normal = Vec3(0.0f, -1.0f, 0.0f);
    area.power = Rgb(0.03f);

    VplRenderer renderer(context(), scene);
    RenderOptions options;
    options.width = options.height = kShadingSize;
    options.shadow_resolution = 32;
    options.batch = 2;
    options.clamp = 0.2f;
    options.vsl_radius = 0.01f;
    const Image image = renderer.render({vpls}, options);

    const SubpixelSchedule schedule = subpixel_schedule(options);
    const float d_min = options.clamp * std::sqrt(32.0f);
    const float vsl_radius = options.vsl_radius * std::sqrt(32.0f);
    const material::ClosureParams receiver = testing::closure_of(glossy);
    int compared = 0, released = 0;
    float worst = 0.0f;
    for (int y = 0; y < kShadingSize; ++y) {
        for (int x = 0; x < kShadingSize; ++x) {
            if (!testing::cast_camera_ray(scene, kShadingSize, kShadingSize, x, y)) continue;
            Rgb expected(0.0f), all_clamped(0.0f);
            for (size_t i = 0; i < vpls.size(); ++i) {
                const Vec2 at = schedule.position(schedule.position_of(i));
                const std::optional<testing::CpuHit> hit =
                    testing::cast_camera_ray(scene, kShadingSize, kShadingSize, x, y, at);
                if (!hit) continue;
                const Vec3 eye = scene.camera.position();
                expected += testing::cpu_contribution(vpls[i], hit->p, hit->ng, receiver, eye,
                                                      d_min, vsl_radius);
                // The same widened lobes, their whole product clamped (before issue 15).
                all_clamped += testing::cpu_contribution(vpls[i], hit->p, hit->ng, receiver, eye,
                                                         d_min, vsl_radius, true);
            }
            ++compared;
            if (max_component(expected) > 1.1f * max_component(all_clamped)) ++released;
            worst = std::max(worst, relative_error(image.at(x, y), expected));
        }
    }
    EXPECT_GT(compared, kShadingSize * kShadingSize / 2);
    // The released glossy light shows in a good share of the pixels (measured: see the record).
    EXPECT_GT(released, compared / 20);
    EXPECT_LT(worst, 1e-3f);
    RecordProperty("released_pixels", std::to_string(released));
    RecordProperty("worst_relative_error", std::to_string(worst));
}

// Without jitter every pixel whose centre sees the lamp shows its emission exactly, whatever the
// number of batches; with jitter it is the mean over the batches' positions, exact where every
// position sees the lamp (pixels away from the quad's edges) and coverage-weighted on them.
TEST_F(ShadingTest, EmittedRadianceIsAddedOnceWhateverTheNumberOfBatches) {
    scene::Material lamp = test::diffuse_material(Rgb(0.5f));
    lamp.emissive = Rgb(0.25f, 0.5f, 1.0f);
    lamp.emissive_strength = 3.0f;
    const scene::Scene scene = floor_scene(lamp);
    // VPLs under the floor: they light nothing the camera sees, but make three batches.
    std::vector<light::Vpl> vpls(3);
    for (light::Vpl& v : vpls) {
        v.type = light::VplType::Point;
        v.position = Vec3(0.0f, -1.0f, 0.0f);
        v.power = Rgb(10.0f);
    }
    VplRenderer renderer(context(), scene);
    RenderOptions options;
    options.width = options.height = 16;
    options.shadow_resolution = 16;
    options.batch = 1;
    options.clamp = 0.0f;
    const auto covered = [&](int x, int y) {
        return bool(testing::cast_camera_ray(scene, 16, 16, x, y));
    };
    RenderTimings timings;
    for (const bool jitter : {false, true}) {
        options.jitter = jitter;
        for (const std::vector<light::Vpl>& list : {std::vector<light::Vpl>{}, vpls}) {
            const Image image = renderer.render({list}, options, &timings);
            EXPECT_EQ(timings.batches, uint32_t(list.size()));
            EXPECT_EQ(timings.g_buffers,
                      jitter ? std::max<uint32_t>(uint32_t(list.size()), 1u) : 1u);
            int compared = 0;
            for (int y = 0; y < 16; ++y) {
                for (int x = 0; x < 16; ++x) {
                    bool inside = covered(x, y);
                    for (int dy = -1; dy <= 1 && jitter; ++dy) {
                        for (int dx = -1; dx <= 1; ++dx)
                            inside = inside && covered(x + dx, y + dy);
                    }
                    if (!inside) continue;
                    ++compared;
                    EXPECT_EQ(image.at(x, y), lamp.emission()) << x << "," << y << " " << jitter;
                }
            }
            EXPECT_GT(compared, jitter ? 80 : 100);
        }
    }
}

// A shading normal tilted away from the geometric one (a bump or normal map, or interpolated
// vertex normals) can face a VPL that lies below the surface's geometric plane. Its light cannot
// reach the upper side (light::vpl_contribution returns 0 there, whatever the visibility test
// says, and so does the path tracer), so the GPU must add nothing either: the shadow cube sees the
// plane's underside at the receiver's own depth and would call it lit. Here the plane's vertex
// normals lean 60° towards +x and a point VPL sits 0.5 below the plane beyond its +x edge, where
// every receiver's tilted normal faces it (n·l > 0) and the geometric normal does not (ng·l < 0):
// the image must be black. The same VPL mirrored above the plane must light it (the test can see
// light through the tilted normals).
TEST_F(ShadingTest, AVplBelowTheGeometricSurfaceLightsNothingWhateverTheShadingNormal) {
    scene::Scene scene = floor_scene(test::diffuse_material(Rgb(0.8f)));
    const float tilt = glm::radians(60.0f);
    scene.meshes[0].normals.assign(4, Vec3(std::sin(tilt), std::cos(tilt), 0.0f));
    VplRenderer renderer(context(), scene);
    RenderOptions options;
    options.width = options.height = kShadingSize;
    options.shadow_resolution = 64;
    options.clamp = 0.0f;
    for (const float height : {-0.5f, 0.5f}) {
        light::Vpl vpl;
        vpl.type = light::VplType::Point;
        vpl.position = Vec3(4.0f, height, 0.0f);
        vpl.power = Rgb(20.0f);
        const Image image = renderer.render({{vpl}}, options);
        int lit = 0;
        for (int y = 0; y < kShadingSize; ++y) {
            for (int x = 0; x < kShadingSize; ++x)
                lit += max_component(image.at(x, y)) > 0.0f;
        }
        if (height < 0.0f) {
            EXPECT_EQ(lit, 0) << "pixels lit from below the plane";
        } else {
            EXPECT_GT(lit, kShadingSize * kShadingSize / 4);
        }
    }
}

}  // namespace
}  // namespace mvpl::render
