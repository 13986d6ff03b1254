// Primitive geometry: flat normals, normal repair, strips and fans, skipped points and lines,
// GLB with interleaved, normalized, sparse and zero-filled accessors, default material.
#include <gtest/gtest.h>

#include "engine/core/image.h"
#include "engine/scene/camera.h"
#include "engine/scene/scene_loader.h"
#include "scene_test_util.h"

namespace mvpl::scene {
namespace {

using test::expect_vec_near;

TEST(GltfGeometry, MissingNormalsGiveFlatUnweldedTriangles) {
    const Scene scene = load_gltf(test::gltf_fixture("flat_normals.gltf"));
    test::expect_valid_meshes(scene);
    ASSERT_EQ(scene.meshes.size(), 3u);

    const Mesh& quad = scene.meshes[0];
    ASSERT_EQ(quad.positions.size(), 6u);  // 4 shared vertices become 2 × 3
    EXPECT_EQ(quad.indices, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5}));
    for (const Vec3& n : quad.normals)
        expect_vec_near(n, Vec3(0, 0, 1));
    // Corner order 0 1 2 0 2 3 carries the per-vertex data along.
    const std::vector<Vec2> uv = {{0, 1}, {1, 1}, {1, 0}, {0, 1}, {1, 0}, {0, 0}};
    ASSERT_EQ(quad.uv0.size(), 6u);
    for (size_t i = 0; i < 6; ++i)
        EXPECT_EQ(quad.uv0[i], uv[i]) << i;
    expect_vec_near(quad.positions[4], Vec3(1, 1, 0));

    const Mesh& tilt = scene.meshes[1];
    ASSERT_EQ(tilt.triangle_count(), 2u);  // the degenerate triangle is kept
    for (int c = 0; c < 3; ++c)
        expect_vec_near(tilt.normals[size_t(c)], glm::normalize(Vec3(0, -1, 1)));
}

TEST(GltfGeometry, ZeroLengthNormalsAreReplacedByTheFaceNormal) {
    const Scene scene = load_gltf(test::gltf_fixture("flat_normals.gltf"));
    const Mesh& repair = scene.meshes[2];
    ASSERT_EQ(repair.positions.size(), 3u);  // normals present: stays welded
    for (const Vec3& n : repair.normals)
        expect_vec_near(n, Vec3(0, 0, 1));
}

TEST(GltfGeometry, StripsAndFansBecomeTrianglesWithTheirWinding) {
    const Scene scene = load_gltf(test::gltf_fixture("strip_fan.gltf"));
    test::expect_valid_meshes(scene);
    // The points and lines primitives of "mixed" are skipped.
    ASSERT_EQ(scene.meshes.size(), 2u);

    const Mesh& strip = scene.meshes[0];
    EXPECT_EQ(strip.name, "mixed primitive 1");
    ASSERT_EQ(strip.triangle_count(), 2u);
    // Strip 0 1 2 3 → (0 1 2), (1 3 2).
    expect_vec_near(strip.positions[3], Vec3(1, 0, 0));
    expect_vec_near(strip.positions[4], Vec3(1, 1, 0));
    expect_vec_near(strip.positions[5], Vec3(0, 1, 0));

    const Mesh& fan = scene.meshes[1];
    ASSERT_EQ(fan.triangle_count(), 2u);
    // Fan 0 1 2 3 → (1 2 0), (2 3 0), placed at z = 1.
    expect_vec_near(fan.positions[0], Vec3(1, 0, 1));
    expect_vec_near(fan.positions[1], Vec3(1, 1, 1));
    expect_vec_near(fan.positions[2], Vec3(0, 0, 1));
    expect_vec_near(fan.positions[3], Vec3(1, 1, 1));
    expect_vec_near(fan.positions[4], Vec3(0, 1, 1));
    for (const Mesh* mesh : {&strip, &fan}) {
        for (const Vec3& n : mesh->normals)
            expect_vec_near(n, Vec3(0, 0, 1));
    }
}

class GltfBinary : public ::testing::Test {
protected:
    static void SetUpTestSuite() { s_scene = new Scene(load_scene(test::gltf_fixture("box.glb"))); }
    static void TearDownTestSuite() {
        delete s_scene;
        s_scene = nullptr;
    }
    static Scene* s_scene;
};
Scene* GltfBinary::s_scene = nullptr;

TEST_F(GltfBinary, InterleavedCubeWithTangentsAndNormalizedUvs) {
    test::expect_valid_meshes(*s_scene);
    ASSERT_EQ(s_scene->meshes.size(), 3u);
    const Mesh& box = s_scene->meshes[0];
    EXPECT_EQ(box.name, "box");
    EXPECT_EQ(box.positions.size(), 24u);
    EXPECT_EQ(box.triangle_count(), 12u);
    ASSERT_EQ(box.tangents.size(), 24u);
    ASSERT_EQ(box.uv0.size(), 24u);
    EXPECT_TRUE(box.uv1.empty());
    for (const Vec4& t : box.tangents) {
        EXPECT_FLOAT_EQ(t.w, 1.0f);
        EXPECT_NEAR(glm::length(Vec3(t)), 1.0f, 1e-6f);
    }
    for (const Vec2& uv : box.uv0) {
        EXPECT_TRUE(uv.x == 0.0f || uv.x == 1.0f);
        EXPECT_TRUE(uv.y == 0.0f || uv.y == 1.0f);
    }
    Bounds bounds;
    for (const Vec3& p : box.positions)
        bounds.extend(p);
    expect_vec_near(bounds.lo, Vec3(-0.5f, 0.5f, -0.5f));
    expect_vec_near(bounds.hi, Vec3(0.5f, 1.5f, 0.5f));
    for (size_t t = 0; t < box.triangle_count(); ++t) {
        const Vec3 n = box.normals[box.indices[3 * t]];
        EXPECT_GT(glm::dot(test::winding_normal(box, t), n), 0.0f);
        // Outward: the normal points away from the box centre (0, 1, 0).
        EXPECT_GT(glm::dot(box.positions[box.indices[3 * t]] - Vec3(0, 1, 0), n), 0.0f);
    }
}

TEST_F(GltfBinary, ImageFromABufferViewIsDecoded) {
    ASSERT_EQ(s_scene->materials.size(), 2u);  // boxmat and the default material
    const Material& material = s_scene->materials[0];
    ASSERT_TRUE(material.base_color_texture.valid());
    const Texture& texture = s_scene->textures[size_t(material.base_color_texture.texture)];
    ASSERT_EQ(texture.width, 1);
    ASSERT_EQ(texture.height, 1);
    EXPECT_FLOAT_EQ(texture.texels[0].r, 1.0f);
    EXPECT_FLOAT_EQ(texture.texels[0].g, srgb_to_linear(128.0f / 255.0f));
    EXPECT_FLOAT_EQ(texture.texels[0].b, 0.0f);
    EXPECT_FLOAT_EQ(texture.texels[0].a, 1.0f);
}

TEST_F(GltfBinary, SparseAccessorsOverrideTheirBaseAndZeroFill) {
    const Mesh& sparse = s_scene->meshes[1];
    ASSERT_EQ(sparse.positions.size(), 3u);
    expect_vec_near(sparse.positions[0], Vec3(5, 0, 0));
    expect_vec_near(sparse.positions[1], Vec3(7, 0, 0));
    expect_vec_near(sparse.positions[2], Vec3(5, 1, 0));
    ASSERT_EQ(sparse.uv1.size(), 3u);
    EXPECT_EQ(sparse.uv1[0], Vec2(0.5f, 0.5f));
    EXPECT_EQ(sparse.uv1[1], Vec2(0.0f, 0.0f));
    EXPECT_EQ(sparse.uv1[2], Vec2(1.0f, 1.0f));
    EXPECT_TRUE(sparse.uv0.empty());
}

TEST_F(GltfBinary, UnsignedByteIndicesKeepTheirOrder) {
    const Mesh& mesh = s_scene->meshes[2];
    ASSERT_EQ(mesh.positions.size(), 3u);
    expect_vec_near(mesh.positions[0], Vec3(-5, 1, 0));
    expect_vec_near(mesh.positions[1], Vec3(-4, 0, 0));
    expect_vec_near(mesh.positions[2], Vec3(-5, 0, 0));
    for (const Vec3& n : mesh.normals)
        expect_vec_near(n, Vec3(0, 0, -1));
    EXPECT_EQ(mesh.material, 1);  // no material: the appended default
}

TEST(GltfDefaults, NoScenesNoCameraNoMaterial) {
    const Scene scene = load_gltf(test::gltf_fixture("defaults.gltf"));
    test::expect_valid_meshes(scene);
    EXPECT_EQ(scene.path, test::gltf_fixture("defaults.gltf"));
    // Every parentless node, depth first: node 0, its child 1, then node 2.
    ASSERT_EQ(scene.meshes.size(), 3u);
    expect_vec_near(scene.meshes[0].positions[2], Vec3(0, 2, 0));
    expect_vec_near(scene.meshes[1].positions[2], Vec3(0, 2, -4));
    expect_vec_near(scene.meshes[2].positions[2], Vec3(3, 2, 0));

    ASSERT_EQ(scene.materials.size(), 1u);
    const Material& material = scene.materials[0];
    EXPECT_EQ(material.name, "default");
    EXPECT_EQ(material.base_color, Rgb(1.0f));
    EXPECT_EQ(material.metallic, 1.0f);
    EXPECT_EQ(material.roughness, 1.0f);
    EXPECT_FALSE(material.is_emissive());
    for (const Mesh& mesh : scene.meshes)
        EXPECT_EQ(mesh.material, 0);

    EXPECT_FALSE(scene.has_camera);
    const Camera framed = frame_bounds(scene.bounds());
    EXPECT_EQ(scene.camera.camera_to_world, framed.camera_to_world);
    EXPECT_EQ(scene.camera.yfov, framed.yfov);
    EXPECT_EQ(scene.camera.znear, framed.znear);
    EXPECT_TRUE(scene.lights.empty());
}

}  // namespace
}  // namespace mvpl::scene
