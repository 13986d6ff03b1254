// Materials: every field, texture transforms, colour spaces, image formats, samplers.
#include <gtest/gtest.h>

#include "engine/core/image.h"
#include "engine/scene/scene_loader.h"
#include "scene_test_util.h"

namespace mvpl::scene {
namespace {

class GltfMaterials : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        s_scene = new Scene(load_gltf(test::gltf_fixture("materials.gltf")));
    }
    static void TearDownTestSuite() {
        delete s_scene;
        s_scene = nullptr;
    }
    static const Texture& texture_of(const TextureRef& ref) {
        return s_scene->textures.at(size_t(ref.texture));
    }
    static Scene* s_scene;
};
Scene* GltfMaterials::s_scene = nullptr;

void expect_texel(const Vec4& actual, const Vec4& expected) {
    for (int i = 0; i < 4; ++i)
        EXPECT_NEAR(actual[i], expected[i], 1e-6f) << "channel " << i;
}

TEST_F(GltfMaterials, PrimitivesGetTheirMaterialsAndTheDefaultIsAppended) {
    test::expect_valid_meshes(*s_scene);
    ASSERT_EQ(s_scene->materials.size(), 4u);
    ASSERT_EQ(s_scene->meshes.size(), 4u);
    for (int i = 0; i < 4; ++i)
        EXPECT_EQ(s_scene->meshes[size_t(i)].material, i);
    EXPECT_EQ(s_scene->materials[3].name, "default");
    EXPECT_EQ(s_scene->meshes[0].uv0.size(), 3u);
    EXPECT_EQ(s_scene->meshes[0].uv1.size(), 3u);
}

TEST_F(GltfMaterials, FactorsAndExtensions) {
    const Material& m = s_scene->materials[0];
    EXPECT_EQ(m.name, "full");
    EXPECT_EQ(m.base_color, Rgb(0.5f, 0.25f, 1.0f));
    EXPECT_FLOAT_EQ(m.base_alpha, 0.3f);
    EXPECT_EQ(m.alpha_mode, AlphaMode::Mask);
    EXPECT_FLOAT_EQ(m.alpha_cutoff, 0.25f);
    EXPECT_FLOAT_EQ(m.metallic, 0.2f);
    EXPECT_FLOAT_EQ(m.roughness, 0.7f);
    EXPECT_FLOAT_EQ(m.normal_scale, 0.8f);
    EXPECT_EQ(m.emissive, Rgb(1.0f, 0.5f, 0.25f));
    EXPECT_FLOAT_EQ(m.emissive_strength, 4.0f);
    EXPECT_EQ(m.emission(), Rgb(4.0f, 2.0f, 1.0f));
    EXPECT_FLOAT_EQ(m.specular, 0.6f);
    EXPECT_EQ(m.specular_color, Rgb(1.2f, 0.9f, 0.8f));
    EXPECT_FLOAT_EQ(m.ior, 1.33f);
    EXPECT_TRUE(m.double_sided);
}

TEST_F(GltfMaterials, TextureReferencesAndTransforms) {
    const Material& m = s_scene->materials[0];
    ASSERT_TRUE(m.base_color_texture.valid());
    EXPECT_EQ(m.base_color_texture.texcoord, 1);  // KHR_texture_transform's texCoord override
    EXPECT_EQ(m.base_color_texture.offset, Vec2(0.5f, 0.25f));
    EXPECT_FLOAT_EQ(m.base_color_texture.rotation, 0.3f);
    EXPECT_EQ(m.base_color_texture.scale, Vec2(2.0f, 3.0f));

    // The same texture, same colour space: one Scene texture, its own (identity) transform.
    EXPECT_EQ(m.emissive_texture.texture, m.base_color_texture.texture);
    EXPECT_EQ(m.emissive_texture.texcoord, 0);
    EXPECT_EQ(m.emissive_texture.offset, Vec2(0.0f));
    EXPECT_EQ(m.emissive_texture.scale, Vec2(1.0f));

    ASSERT_TRUE(m.normal_texture.valid());
    EXPECT_EQ(m.normal_texture.texcoord, 1);
    EXPECT_EQ(m.specular_texture.texture, m.normal_texture.texture);
    ASSERT_TRUE(m.metallic_roughness_texture.valid());
    ASSERT_TRUE(m.specular_color_texture.valid());
    EXPECT_EQ(m.specular_color_texture.offset, Vec2(0.1f, 0.2f));

    // One image used as a colour (sRGB) and as data (linear): two Scene textures.
    const Material& linear_use = s_scene->materials[1];
    ASSERT_TRUE(linear_use.metallic_roughness_texture.valid());
    EXPECT_NE(linear_use.metallic_roughness_texture.texture, m.base_color_texture.texture);
    EXPECT_EQ(s_scene->textures.size(), 5u);
}

TEST_F(GltfMaterials, SrgbTexturesAreDecodedAndLinearOnesAreNot) {
    const Texture& srgb = texture_of(s_scene->materials[0].base_color_texture);
    const Texture& linear = texture_of(s_scene->materials[1].metallic_roughness_texture);
    for (const Texture* t : {&srgb, &linear}) {
        ASSERT_EQ(t->width, 2);
        ASSERT_EQ(t->height, 2);
        ASSERT_EQ(t->texels.size(), 4u);
        expect_texel(t->texels[0], Vec4(1, 0, 0, 1));  // row 0 is the top of the image
        expect_texel(t->texels[1], Vec4(0, 1, 0, 1));
        expect_texel(t->texels[2], Vec4(0, 0, 1, 1));
    }
    const float grey = 128.0f / 255.0f;
    expect_texel(srgb.texels[3], Vec4(Vec3(srgb_to_linear(grey)), 1.0f));
    expect_texel(linear.texels[3], Vec4(Vec3(grey), 1.0f));
}

TEST_F(GltfMaterials, SamplersSetWrapModesAndFilter) {
    const Texture& sampled = texture_of(s_scene->materials[0].base_color_texture);
    EXPECT_EQ(sampled.filter, Filter::Nearest);
    EXPECT_EQ(sampled.wrap_s, Wrap::ClampToEdge);
    EXPECT_EQ(sampled.wrap_t, Wrap::MirroredRepeat);
    const Texture& unsampled = texture_of(s_scene->materials[0].metallic_roughness_texture);
    EXPECT_EQ(unsampled.filter, Filter::Linear);
    EXPECT_EQ(unsampled.wrap_s, Wrap::Repeat);
    EXPECT_EQ(unsampled.wrap_t, Wrap::Repeat);
}

TEST_F(GltfMaterials, GreyAlphaAndSixteenBitImagesFillFourChannels) {
    const Material& m = s_scene->materials[0];
    const Texture& grey = texture_of(m.metallic_roughness_texture);
    ASSERT_EQ(grey.texels.size(), 2u);
    expect_texel(grey.texels[0], Vec4(0, 0, 0, 1));
    expect_texel(grey.texels[1], Vec4(Vec3(188.0f / 255.0f), 1.0f));

    const Texture& wide = texture_of(m.normal_texture);
    ASSERT_EQ(wide.texels.size(), 1u);
    expect_texel(wide.texels[0], Vec4(1.0f, 32768.0f / 65535.0f, 0.0f, 16384.0f / 65535.0f));

    const Texture& grey_alpha = texture_of(m.specular_color_texture);  // sRGB colour, linear alpha
    ASSERT_EQ(grey_alpha.texels.size(), 1u);
    expect_texel(grey_alpha.texels[0], Vec4(Vec3(srgb_to_linear(100.0f / 255.0f)), 50.0f / 255.0f));
}

TEST_F(GltfMaterials, AbsentPropertiesTakeTheSpecDefaults) {
    const Material& m = s_scene->materials[2];
    EXPECT_EQ(m.name, "defaults");
    EXPECT_EQ(m.base_color, Rgb(1.0f));
    EXPECT_EQ(m.metallic, 1.0f);
    EXPECT_EQ(m.roughness, 1.0f);
    EXPECT_EQ(m.emissive, Rgb(0.0f));
    EXPECT_EQ(m.emissive_strength, 1.0f);
    EXPECT_EQ(m.specular, 1.0f);
    EXPECT_EQ(m.specular_color, Rgb(1.0f));
    EXPECT_EQ(m.ior, 1.5f);
    EXPECT_EQ(m.normal_scale, 1.0f);
    EXPECT_FALSE(m.double_sided);
    for (const TextureRef* ref :
         {&m.base_color_texture, &m.metallic_roughness_texture, &m.normal_texture,
          &m.emissive_texture, &m.specular_texture, &m.specular_color_texture}) {
        EXPECT_FALSE(ref->valid());
    }
}

}  // namespace
}  // namespace mvpl::scene
