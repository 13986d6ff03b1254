#include <gtest/gtest.h>

#include "engine/gpu/command_list.h"
#include "engine/gpu/context.h"
#include "engine/render/g_buffer_pass.h"
#include "engine/render/scene_geometry.h"
#include "tests/gpu/gpu_test.h"
#include "tests/render/render_test_util.h"
#include "tests/support/scene_builder.h"

namespace mvpl::render {
namespace {

using GBufferTest = gpu::testing::GpuTest;

// A floor facing the camera and, behind it, a wall whose winding normal points away from the
// camera (a back face: double-sided, emissive, so its flags and the front-only emission show).
scene::Scene two_quads() {
    scene::Scene s;
    scene::Material floor = test::diffuse_material(Rgb(0.2f, 0.5f, 0.7f));
    scene::Material wall;
    wall.base_color = Rgb(0.9f, 0.1f, 0.3f);
    wall.metallic = 0.25f;
    wall.roughness = 0.4f;
    wall.specular = 0.7f;
    wall.specular_color = Rgb(1.0f, 0.9f, 0.8f);
    wall.ior = 1.7f;
    wall.emissive = Rgb(2.0f, 3.0f, 4.0f);
    wall.double_sided = true;
    s.materials = {floor, wall};
    s.meshes.push_back(test::make_quad(Vec3(-1, 0, -1), Vec3(0, 0, 2), Vec3(2, 0, 0), 0));
    // cross(a, b) = cross(x, y) = +z… reversed to −z: a = y, b = x.
    s.meshes.push_back(test::make_quad(Vec3(-1, 0, -1), Vec3(0, 1.5f, 0), Vec3(2, 0, 0), 1));
    s.camera = test::look_at(Vec3(0.2f, 1.3f, 2.4f), Vec3(0, 0.2f, -0.3f), 0.9f);
    s.has_camera = true;
    return s;
}

TEST_F(GBufferTest, MatchesACpuRayCastThroughPixelCentres) {
    const scene::Scene scene = two_quads();
    constexpr int kWidth = 64;
    constexpr int kHeight = 48;  // not square: the aspect must follow width / height
    const SceneGeometry geometry(context(), scene);
    GBufferPass pass(context(), geometry, kWidth, kHeight);
    context().submit_and_wait([&](gpu::CommandList& cmd) { pass.record(cmd, scene.camera); });
    const std::vector<GBufferTexel> texels = pass.download();
    ASSERT_EQ(texels.size(), size_t(kWidth * kHeight));

    const material::ClosureParams wall = testing::closure_of(scene.materials[1]);
    int coverage_mismatches = 0;
    int compared = 0;
    int back_faces = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const GBufferTexel& t = texels[size_t(y) * kWidth + x];
            const std::optional<testing::CpuHit> hit =
                testing::cast_camera_ray(scene, kWidth, kHeight, x, y);
            if (t.covered != hit.has_value()) {
                ++coverage_mismatches;
                continue;
            }
            if (!hit) continue;
            // A pixel centre on the floor/wall seam may pick either surface.
            if (glm::dot(t.geometric_normal, hit->ng) < 0.5f) {
                ++coverage_mismatches;
                continue;
            }
            ++compared;
            const float distance = glm::length(hit->p - scene.camera.position());
            // Float rasterisation: interpolated positions carry ~1e-6 relative error.
            EXPECT_LT(glm::length(t.position - hit->p), 1e-4f * distance) << x << "," << y;
            EXPECT_LT(glm::length(t.geometric_normal - hit->ng), 1e-5f) << x << "," << y;
            EXPECT_LT(glm::length(t.shading_normal - hit->ng), 1e-5f) << x << "," << y;
            EXPECT_EQ(t.front_face, hit->front_face) << x << "," << y;
            if (hit->mesh == 1) {
                ++back_faces;
                EXPECT_TRUE(t.double_sided);
                EXPECT_EQ(t.emission, Rgb(0.0f)) << "emission is front-face only";
                EXPECT_EQ(t.closure.base_color, wall.base_color);
                EXPECT_EQ(t.closure.metallic, wall.metallic);
                EXPECT_EQ(t.closure.roughness, wall.roughness);
                EXPECT_EQ(t.closure.specular, wall.specular);
                EXPECT_EQ(t.closure.specular_color, wall.specular_color);
                EXPECT_EQ(t.closure.ior, wall.ior);
            } else {
                EXPECT_FALSE(t.double_sided);
                EXPECT_EQ(t.closure.base_color, scene.materials[0].base_color);
            }
        }
    }
    EXPECT_LE(coverage_mismatches, 2);
    EXPECT_GT(compared, kWidth * kHeight / 3);
    EXPECT_GT(back_faces, 100);
}

// A sub-pixel position shifts the whole image: pixel (x, y) then holds the surface that the ray
// through (x + s.x, y + s.y) hits, not the pixel centre's (which is farther than the tolerance).
TEST_F(GBufferTest, ASubpixelPositionMatchesTheRayThroughThatPoint) {
    const scene::Scene scene = two_quads();
    constexpr int kWidth = 64;
    constexpr int kHeight = 48;
    const SceneGeometry geometry(context(), scene);
    GBufferPass pass(context(), geometry, kWidth, kHeight);
    for (const Vec2 s : {Vec2(0.1f, 0.85f), Vec2(0.9f, 0.2f)}) {
        context().submit_and_wait(
            [&](gpu::CommandList& cmd) { pass.record(cmd, scene.camera, s); });
        const std::vector<GBufferTexel> texels = pass.download();
        int compared = 0, mismatches = 0, off_centre = 0;
        for (int y = 0; y < kHeight; ++y) {
            for (int x = 0; x < kWidth; ++x) {
                const GBufferTexel& t = texels[size_t(y) * kWidth + x];
                const std::optional<testing::CpuHit> hit =
                    testing::cast_camera_ray(scene, kWidth, kHeight, x, y, s);
                const std::optional<testing::CpuHit> centre =
                    testing::cast_camera_ray(scene, kWidth, kHeight, x, y);
                if (t.covered != hit.has_value() ||
                    (hit && glm::dot(t.geometric_normal, hit->ng) < 0.5f)) {
                    ++mismatches;
                    continue;
                }
                if (!hit) continue;
                ++compared;
                const float distance = glm::length(hit->p - scene.camera.position());
                EXPECT_LT(glm::length(t.position - hit->p), 1e-4f * distance) << x << "," << y;
                if (centre && glm::length(t.position - centre->p) > 1e-3f * distance) ++off_centre;
            }
        }
        EXPECT_LE(mismatches, 2);
        EXPECT_GT(compared, kWidth * kHeight / 3);
        EXPECT_GT(off_centre, compared * 9 / 10);
    }
}

TEST_F(GBufferTest, FrontFacesCarryTheirEmission) {
    scene::Scene scene = two_quads();
    // Look at the wall from behind it, where its winding normal points.
    scene.camera = test::look_at(Vec3(0.1f, 0.7f, -3.0f), Vec3(0, 0.7f, -1.0f), 0.8f);
    const SceneGeometry geometry(context(), scene);
    GBufferPass pass(context(), geometry, 16, 16);
    context().submit_and_wait([&](gpu::CommandList& cmd) { pass.record(cmd, scene.camera); });
    const GBufferTexel centre = pass.download()[8 * 16 + 8];
    ASSERT_TRUE(centre.covered);
    EXPECT_TRUE(centre.front_face);
    EXPECT_EQ(centre.emission, scene.materials[1].emission());
}

TEST_F(GBufferTest, ShadingNormalsAreTheInterpolatedVertexNormals) {
    scene::Scene scene;
    scene.materials = {test::diffuse_material(Rgb(0.5f))};
    scene.meshes.push_back(test::make_icosphere(Vec3(0.1f, -0.2f, 0.0f), 1.0f, 1, false, 0));
    scene.camera = test::look_at(Vec3(0.5f, 1.0f, 3.5f), Vec3(0.1f, -0.2f, 0.0f), 0.8f);
    constexpr int kSize = 48;
    const SceneGeometry geometry(context(), scene);
    GBufferPass pass(context(), geometry, kSize, kSize);
    context().submit_and_wait([&](gpu::CommandList& cmd) { pass.record(cmd, scene.camera); });
    const std::vector<GBufferTexel> texels = pass.download();
    int compared = 0;
    int curved = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const GBufferTexel& t = texels[size_t(y) * kSize + x];
            const std::optional<testing::CpuHit> hit =
                testing::cast_camera_ray(scene, kSize, kSize, x, y);
            // Only pixels that both see in the same triangle (edges may go either way).
            if (!hit || !t.covered || glm::length(t.geometric_normal - hit->ng) > 1e-4f) continue;
            ++compared;
            curved += glm::length(hit->ns - hit->ng) > 0.05f;
            const float distance = glm::length(hit->p - scene.camera.position());
            EXPECT_LT(glm::length(t.position - hit->p), 1e-4f * distance) << x << "," << y;
            // Perspective-correct interpolation reproduces the ray's barycentrics.
            EXPECT_LT(glm::length(t.shading_normal - hit->ns), 1e-4f) << x << "," << y;
            EXPECT_TRUE(t.front_face);
        }
    }
    EXPECT_GT(compared, kSize * kSize / 4);
    EXPECT_GT(curved, compared / 4) << "the test must see normals that differ from the faces'";
}

}  // namespace
}  // namespace mvpl::render
