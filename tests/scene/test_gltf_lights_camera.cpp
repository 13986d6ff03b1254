// KHR_lights_punctual lights and the camera.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "engine/scene/camera.h"
#include "engine/scene/scene_loader.h"
#include "scene_test_util.h"

namespace mvpl::scene {
namespace {

using test::expect_vec_near;

class GltfLightsCamera : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        s_scene = new Scene(load_gltf(test::gltf_fixture("lights_camera.gltf")));
    }
    static void TearDownTestSuite() {
        delete s_scene;
        s_scene = nullptr;
    }
    static Scene* s_scene;
};
Scene* GltfLightsCamera::s_scene = nullptr;

TEST_F(GltfLightsCamera, PointLightIntensityIsColourTimesIntensity) {
    ASSERT_EQ(s_scene->lights.size(), 4u);
    const Light& bulb = s_scene->lights[0];
    EXPECT_EQ(bulb.name, "bulb");
    EXPECT_EQ(bulb.type, LightType::Point);
    expect_vec_near(bulb.intensity, Rgb(10.0f, 5.0f, 2.5f));
    expect_vec_near(bulb.position, Vec3(1, 2, 3));
}

TEST_F(GltfLightsCamera, SpotLightsShineDownTheNodesMinusZ) {
    const Light& spot_default = s_scene->lights[1];
    EXPECT_EQ(spot_default.type, LightType::Spot);
    expect_vec_near(spot_default.intensity, Rgb(5.0f));
    EXPECT_FLOAT_EQ(spot_default.inner_cone, 0.0f);
    EXPECT_NEAR(spot_default.outer_cone, kPi / 4.0f, 1e-6f);
    expect_vec_near(spot_default.position, Vec3(0, 5, 0));
    expect_vec_near(spot_default.direction, Vec3(0, -1, 0));

    const Light& spot = s_scene->lights[2];
    EXPECT_FLOAT_EQ(spot.inner_cone, 0.1f);
    EXPECT_FLOAT_EQ(spot.outer_cone, 0.5f);
    expect_vec_near(spot.intensity, Rgb(1.0f));  // intensity and colour default to 1
    expect_vec_near(spot.direction, Vec3(0, 0, -1));
}

TEST_F(GltfLightsCamera, DirectionalLightDirectionIsNormalisedThroughScaledParents) {
    const Light& sun = s_scene->lights[3];
    EXPECT_EQ(sun.name, "sun");
    EXPECT_EQ(sun.type, LightType::Directional);
    expect_vec_near(sun.intensity, Rgb(2.0f));
    expect_vec_near(sun.direction, Vec3(-1, 0, 0));
}

TEST_F(GltfLightsCamera, FirstPerspectiveCameraWithScaleRemoved) {
    // The orthographic camera comes first in traversal order and is skipped; the second
    // perspective camera comes later and is ignored.
    ASSERT_TRUE(s_scene->has_camera);
    const Camera& camera = s_scene->camera;
    EXPECT_FLOAT_EQ(camera.yfov, 0.5f);
    EXPECT_FLOAT_EQ(camera.znear, 0.05f);
    expect_vec_near(camera.position(), Vec3(0, 2, 10));
    // Turned half around Y under a parent scaled by 2: a rigid frame looking down +Z.
    expect_vec_near(Vec3(camera.camera_to_world[0]), Vec3(-1, 0, 0));
    expect_vec_near(Vec3(camera.camera_to_world[1]), Vec3(0, 1, 0));
    expect_vec_near(Vec3(camera.camera_to_world[2]), Vec3(0, 0, -1));
    EXPECT_EQ(camera.camera_to_world[0].w, 0.0f);
    EXPECT_EQ(camera.camera_to_world[3].w, 1.0f);
}

// Camera rays start on the near plane (view depth znear), where the G-buffer clips, whatever the
// pixel: far off-axis that is many times znear from the eye.
TEST(CameraRay, StartsOnTheNearPlane) {
    Camera camera;
    camera.camera_to_world = glm::translate(Mat4(1.0f), Vec3(1, 2, 3)) *
                             glm::rotate(Mat4(1.0f), 0.5f, glm::normalize(Vec3(1, 1, 0)));
    camera.yfov = 3.1f;
    camera.znear = 0.25f;
    const Vec3 eye = camera.position();
    const Vec3 forward = -Vec3(camera.camera_to_world[2]);
    for (const Vec2 film : {Vec2(32, 32), Vec2(0.5f, 0.5f), Vec2(63.5f, 10), Vec2(5, 60)}) {
        const CameraRay ray = generate_camera_ray(camera, 64, 64, film);
        EXPECT_NEAR(glm::dot(ray.origin - eye, forward), camera.znear, 1e-4f);
        // On the line from the eye through the pixel.
        EXPECT_NEAR(glm::length(glm::cross(ray.origin - eye, ray.direction)), 0.0f, 1e-3f);
        EXPECT_GT(glm::dot(ray.origin - eye, ray.direction), 0.0f);
    }
    EXPECT_GT(glm::length(generate_camera_ray(camera, 64, 64, Vec2(0.5f, 32)).origin - eye),
              10.0f * camera.znear);
}

}  // namespace
}  // namespace mvpl::scene
