// Node transforms: nested TRS, matrices, normals through the inverse transpose, mirrors.
#include <gtest/gtest.h>

#include "engine/scene/scene_loader.h"
#include "scene_test_util.h"

namespace mvpl::scene {
namespace {

using test::expect_vec_near;

class GltfTransforms : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        s_scene = new Scene(load_gltf(test::gltf_fixture("transforms.gltf")));
    }
    static void TearDownTestSuite() {
        delete s_scene;
        s_scene = nullptr;
    }
    static Scene* s_scene;
};
Scene* GltfTransforms::s_scene = nullptr;

TEST_F(GltfTransforms, ShowsTheDefaultSceneOnly) {
    // Scene 0 holds the node "unused"; "scene": 1 selects the other one.
    ASSERT_EQ(s_scene->meshes.size(), 3u);
    EXPECT_EQ(s_scene->meshes[0].name, "tri");
    EXPECT_EQ(s_scene->meshes[1].name, "slant");
    EXPECT_EQ(s_scene->meshes[2].name, "tri");
    test::expect_valid_meshes(*s_scene);
}

TEST_F(GltfTransforms, NestedTrsComposesParentTimesChildAsTranslateRotateScale) {
    // parent: T(10,0,0) · Rz(90°) · S(2); child: T(0,1,0).
    const Mesh& mesh = s_scene->meshes[0];
    ASSERT_EQ(mesh.positions.size(), 3u);
    expect_vec_near(mesh.positions[0], Vec3(8, 0, 0));
    expect_vec_near(mesh.positions[1], Vec3(8, 2, 0));
    expect_vec_near(mesh.positions[2], Vec3(6, 0, 0));
    for (const Vec3& n : mesh.normals)
        expect_vec_near(n, Vec3(0, 0, 1));
    EXPECT_EQ(mesh.indices, (std::vector<uint32_t>{0, 1, 2}));
}

TEST_F(GltfTransforms, MatrixIsColumnMajorAndNormalsUseTheInverseTranspose) {
    // matrix = T(0,0,-5) · S(2,1,1); the file normal (1,1,0)/√2 becomes ∝ (1,2,0).
    const Mesh& mesh = s_scene->meshes[1];
    ASSERT_EQ(mesh.positions.size(), 3u);
    expect_vec_near(mesh.positions[0], Vec3(0, 0, -5));
    expect_vec_near(mesh.positions[1], Vec3(0, 0, -4));
    expect_vec_near(mesh.positions[2], Vec3(2, -1, -5));
    const Vec3 expected = glm::normalize(Vec3(1, 2, 0));
    for (const Vec3& n : mesh.normals)
        expect_vec_near(n, expected);
    // The transformed normal is the true normal of the transformed triangle.
    expect_vec_near(glm::normalize(test::winding_normal(mesh, 0)), expected);
}

TEST_F(GltfTransforms, NegativeScaleFlipsTheWindingSoTheFrontFaceStays) {
    const Mesh& mesh = s_scene->meshes[2];
    ASSERT_EQ(mesh.positions.size(), 3u);
    expect_vec_near(mesh.positions[0], Vec3(0, 0, 0));
    expect_vec_near(mesh.positions[1], Vec3(-1, 0, 0));
    expect_vec_near(mesh.positions[2], Vec3(0, 1, 0));
    for (const Vec3& n : mesh.normals)
        expect_vec_near(n, Vec3(0, 0, 1));
    EXPECT_EQ(mesh.indices, (std::vector<uint32_t>{0, 2, 1}));
}

TEST_F(GltfTransforms, EveryWindingAgreesWithItsVertexNormals) {
    for (const Mesh& mesh : s_scene->meshes) {
        for (size_t t = 0; t < mesh.triangle_count(); ++t) {
            const Vec3 face = test::winding_normal(mesh, t);
            for (int c = 0; c < 3; ++c) {
                EXPECT_GT(glm::dot(face, mesh.normals[mesh.indices[3 * t + size_t(c)]]), 0.0f)
                    << mesh.name << " triangle " << t;
            }
        }
    }
}

}  // namespace
}  // namespace mvpl::scene
