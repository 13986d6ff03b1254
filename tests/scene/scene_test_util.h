#pragma once
// Shared helpers for the scene tests.
#include <gtest/gtest.h>

#include <string>

#include "engine/scene/scene.h"

namespace mvpl::scene::test {

inline std::string gltf_fixture(const std::string& name) {
    return std::string(MVPL_TEST_DATA_DIR) + "/gltf/" + name;
}

// Normal of triangle t from its winding (p1 − p0) × (p2 − p0), not normalised.
inline Vec3 winding_normal(const Mesh& mesh, size_t t) {
    const Vec3& p0 = mesh.positions[mesh.indices[3 * t]];
    const Vec3& p1 = mesh.positions[mesh.indices[3 * t + 1]];
    const Vec3& p2 = mesh.positions[mesh.indices[3 * t + 2]];
    return glm::cross(p1 - p0, p2 - p0);
}

inline void expect_vec_near(const Vec3& actual, const Vec3& expected, float tolerance = 1e-5f) {
    EXPECT_NEAR(actual.x, expected.x, tolerance) << "x";
    EXPECT_NEAR(actual.y, expected.y, tolerance) << "y";
    EXPECT_NEAR(actual.z, expected.z, tolerance) << "z";
}

// What every loaded mesh must satisfy, whatever the file: one unit normal per vertex, finite
// values, whole triangles, indices inside the vertex array, optional arrays empty or complete,
// and a material that exists.
inline void expect_valid_meshes(const Scene& scene) {
    ASSERT_FALSE(scene.meshes.empty());
    for (const Mesh& mesh : scene.meshes) {
        SCOPED_TRACE(mesh.name);
        const size_t n = mesh.positions.size();
        EXPECT_EQ(mesh.normals.size(), n);
        EXPECT_TRUE(mesh.uv0.empty() || mesh.uv0.size() == n);
        EXPECT_TRUE(mesh.uv1.empty() || mesh.uv1.size() == n);
        EXPECT_TRUE(mesh.tangents.empty() || mesh.tangents.size() == n);
        EXPECT_EQ(mesh.indices.size() % 3, 0u);
        EXPECT_GT(mesh.indices.size(), 0u);
        for (size_t i = 0; i < n; ++i) {
            EXPECT_TRUE(is_finite(mesh.positions[i])) << "position " << i;
            EXPECT_TRUE(is_finite(mesh.normals[i])) << "normal " << i;
            EXPECT_NEAR(glm::length(mesh.normals[i]), 1.0f, 1e-4f) << "normal " << i;
        }
        for (const Vec2& uv : mesh.uv0)
            EXPECT_TRUE(std::isfinite(uv.x) && std::isfinite(uv.y));
        for (const Vec2& uv : mesh.uv1)
            EXPECT_TRUE(std::isfinite(uv.x) && std::isfinite(uv.y));
        for (const Vec4& t : mesh.tangents)
            EXPECT_TRUE(is_finite(Vec3(t)) && std::isfinite(t.w));
        for (uint32_t index : mesh.indices)
            EXPECT_LT(index, n);
        EXPECT_GE(mesh.material, 0);
        EXPECT_LT(size_t(mesh.material), scene.materials.size());
    }
}

}  // namespace mvpl::scene::test
