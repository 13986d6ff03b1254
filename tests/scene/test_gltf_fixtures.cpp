// Invariants over every good fixture, the bundled Cornell box, and load_scene's dispatch.
#include <gtest/gtest.h>

#include "engine/core/error.h"
#include "engine/scene/scene_loader.h"
#include "scene_test_util.h"

namespace mvpl::scene {
namespace {

using test::expect_vec_near;

const std::string kCornellBox = std::string(MVPL_ASSETS_DIR) + "/cornell-box/cbox.gltf";

class GoodFixture : public ::testing::TestWithParam<std::string> {};

TEST_P(GoodFixture, LoadsWithValidMeshes) {
    const Scene scene = load_scene(GetParam());
    EXPECT_EQ(scene.path, GetParam());
    test::expect_valid_meshes(scene);
    EXPECT_FALSE(scene.bounds().empty());
    for (const Texture& texture : scene.textures) {
        EXPECT_EQ(texture.texels.size(), size_t(texture.width) * size_t(texture.height));
    }
    for (const Material& material : scene.materials) {
        for (const TextureRef* ref :
             {&material.base_color_texture, &material.metallic_roughness_texture,
              &material.normal_texture, &material.emissive_texture, &material.specular_texture,
              &material.specular_color_texture}) {
            EXPECT_LT(ref->texture, int(scene.textures.size()));
        }
    }
    for (const Light& light : scene.lights)
        EXPECT_NEAR(glm::length(light.direction), 1.0f, 1e-5f);
}

INSTANTIATE_TEST_SUITE_P(Gltf, GoodFixture,
                         ::testing::Values(test::gltf_fixture("transforms.gltf"),
                                           test::gltf_fixture("flat_normals.gltf"),
                                           test::gltf_fixture("strip_fan.gltf"),
                                           test::gltf_fixture("materials.gltf"),
                                           test::gltf_fixture("lights_camera.gltf"),
                                           test::gltf_fixture("defaults.gltf"),
                                           test::gltf_fixture("box.glb"), kCornellBox),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             std::string name = info.param.substr(info.param.find_last_of('/') + 1);
                             for (char& c : name) {
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             }
                             return name;
                         });

TEST(CornellBox, GeometryMaterialsAndCamera) {
    const Scene scene = load_scene(kCornellBox);
    // Index counts in the file: 6 + 6 + 12 + 6 + 6 + 6 + 36 + 36 = 114, three per triangle.
    EXPECT_EQ(scene.triangle_count(), 38u);
    EXPECT_EQ(scene.meshes.size(), 8u);
    const Bounds bounds = scene.bounds();
    expect_vec_near(bounds.lo, Vec3(0.0f), 1e-3f);
    expect_vec_near(bounds.hi, Vec3(556.0f, 548.8f, 559.2f), 1e-3f);

    ASSERT_EQ(scene.materials.size(), 5u);
    const Material& light = scene.materials[4];
    EXPECT_EQ(light.name, "light");
    ASSERT_TRUE(light.is_emissive());
    EXPECT_NEAR(light.emission().r, 18.387f, 1e-4f);
    EXPECT_NEAR(light.emission().g, 18.387 * 0.5975580573231086, 1e-4);
    EXPECT_NEAR(light.emission().b, 18.387 * 0.14975634959482242, 1e-4);
    EXPECT_EQ(scene.meshes[0].material, 4);  // the luminaire
    for (int m = 0; m < 4; ++m)
        EXPECT_FALSE(scene.materials[size_t(m)].is_emissive());
    EXPECT_EQ(scene.materials[0].specular, 0.0f);

    ASSERT_TRUE(scene.has_camera);
    expect_vec_near(scene.camera.position(), Vec3(278.0f, 273.0f, -800.0f), 1e-3f);
    // Turned half around Y: looks down world +Z into the box.
    expect_vec_near(-Vec3(scene.camera.camera_to_world[2]), Vec3(0, 0, 1));
    EXPECT_NEAR(scene.camera.yfov, 0.6860488f, 1e-6f);
    EXPECT_TRUE(scene.lights.empty());
}

TEST(LoadScene, RefusesOtherFormatsByExtension) {
    const std::string path = std::string(MVPL_TEST_DATA_DIR) + "/bad/unknown-extension.xyz";
    try {
        load_scene(path);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(path + ": unsupported scene format", 0), 0u)
            << e.what();
    }
}

TEST(LoadScene, MissingFileIsAnInputError) {
    const std::string path = test::gltf_fixture("does-not-exist.gltf");
    EXPECT_THROW(load_scene(path), InputError);
}

}  // namespace
}  // namespace mvpl::scene
