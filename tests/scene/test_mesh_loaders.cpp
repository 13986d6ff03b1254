// PLY and OBJ loading (engine/scene/ply_loader.h, obj_loader.h): the three PLY encodings and OBJ
// give the same triangles for the same mesh, polygons are fanned, normals and .mtl materials are
// read, bare meshes get the default material and a framing camera, and malformed files are
// refused with a one-line InputError that names the defect.
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "engine/core/error.h"
#include "engine/scene/scene_loader.h"
#include "tests/scene/scene_test_util.h"

namespace mvpl::scene {
namespace {

using test::expect_valid_meshes;
using test::expect_vec_near;
using Triangle = std::array<Vec3, 3>;

std::string mesh_file(const std::string& name) {
    return std::string(MVPL_TEST_DATA_DIR) + "/mesh/" + name;
}
std::string bad_file(const std::string& name) {
    return std::string(MVPL_TEST_DATA_DIR) + "/bad/" + name;
}

// Every triangle's corners in mesh and index order.
std::vector<Triangle> triangles(const Scene& scene) {
    std::vector<Triangle> out;
    for (const Mesh& m : scene.meshes) {
        for (size_t i = 0; i < m.indices.size(); i += 3) {
            out.push_back({m.positions[m.indices[i]], m.positions[m.indices[i + 1]],
                           m.positions[m.indices[i + 2]]});
        }
    }
    return out;
}

// tests/data/mesh/make_meshes.py: a unit cube of six quads and a pentagon, 6·2 + 3 triangles.
constexpr size_t kCubeTriangles = 15;

TEST(MeshLoaders, PlyEncodingsAndObjGiveTheSameTriangles) {
    const Scene ascii = load_scene(mesh_file("cube-ascii.ply"));
    expect_valid_meshes(ascii);
    const std::vector<Triangle> expected = triangles(ascii);
    ASSERT_EQ(expected.size(), kCubeTriangles);
    for (const char* name : {"cube-le.ply", "cube-be.ply", "cube.obj"}) {
        SCOPED_TRACE(name);
        const Scene scene = load_scene(mesh_file(name));
        expect_valid_meshes(scene);
        const std::vector<Triangle> got = triangles(scene);
        ASSERT_EQ(got.size(), expected.size());
        // The same decimal text or float bits on both sides: exactly equal, no tolerance.
        for (size_t t = 0; t < got.size(); ++t) {
            for (int c = 0; c < 3; ++c)
                EXPECT_EQ(got[t][size_t(c)], expected[t][size_t(c)]) << "triangle " << t;
        }
    }
}

TEST(MeshLoaders, PolygonsAreFannedKeepingTheWinding) {
    const Scene scene = load_scene(mesh_file("cube-le.ply"));
    const std::vector<Triangle> tris = triangles(scene);
    ASSERT_EQ(tris.size(), kCubeTriangles);
    // The pentagon (vertices 8..12) is last: (8,9,10), (8,10,11), (8,11,12).
    const Vec3 p0(3, 0, 0), p1(4, 0, 0), p2(4.3f, 1, 0), p3(3.5f, 1.6f, 0), p4(2.7f, 1, 0);
    const Triangle fan[3] = {{p0, p1, p2}, {p0, p2, p3}, {p0, p3, p4}};
    for (size_t t = 0; t < 3; ++t) {
        for (size_t c = 0; c < 3; ++c)
            expect_vec_near(tris[12 + t][c], fan[t][c]);
    }
    // Quads are counter-clockwise seen from outside: every cube normal points away from the
    // centre (flat normals, as the file has none).
    const Mesh& mesh = scene.meshes[0];
    for (size_t t = 0; t < 12; ++t) {
        const Vec3 centre = (tris[t][0] + tris[t][1] + tris[t][2]) / 3.0f;
        EXPECT_GT(glm::dot(mesh.normals[mesh.indices[3 * t]], centre - Vec3(0.5f)), 0.0f)
            << "triangle " << t;
        expect_vec_near(mesh.normals[mesh.indices[3 * t]],
                        glm::normalize(test::winding_normal(mesh, t)));
    }
}

TEST(MeshLoaders, BareMeshGetsDefaultMaterialFramingCameraAndNoLight) {
    const Scene scene = load_scene(mesh_file("cube-ascii.ply"));
    ASSERT_EQ(scene.materials.size(), 1u);
    const Material& m = scene.materials[0];
    expect_vec_near(m.base_color, Vec3(0.5f));
    EXPECT_EQ(m.metallic, 0.0f);
    EXPECT_EQ(m.specular, 0.0f);
    EXPECT_FALSE(m.is_emissive());
    EXPECT_TRUE(scene.lights.empty());
    EXPECT_FALSE(scene.has_camera);
    // frame_bounds puts the camera outside the box, above it and on its +X +Z side (a
    // three-quarter view), looking at the centre, with the image's up in the plane of +Y.
    const Bounds b = scene.bounds();
    const Vec3 eye = scene.camera.position();
    EXPECT_GT(eye.x, b.hi.x);
    EXPECT_GT(eye.y, b.hi.y);
    EXPECT_GT(eye.z, b.hi.z);
    expect_vec_near(-Vec3(scene.camera.camera_to_world[2]), glm::normalize(b.center() - eye));
    EXPECT_NEAR(Vec3(scene.camera.camera_to_world[0]).y, 0.0f, 1e-6f);  // no roll
}

TEST(MeshLoaders, PlyVertexNormalsAreReadAndNormalised) {
    const Scene scene = load_scene(mesh_file("normals.ply"));
    expect_valid_meshes(scene);
    ASSERT_EQ(scene.meshes.size(), 1u);
    const Mesh& mesh = scene.meshes[0];
    ASSERT_EQ(mesh.positions.size(), 3u);  // shared vertices kept: the file has normals
    for (const Vec3& n : mesh.normals)
        expect_vec_near(n, Vec3(0, 0, 1));
}

TEST(MeshLoaders, ObjMaterialsFromMtl) {
    const Scene scene = load_scene(mesh_file("lit.obj"));
    expect_valid_meshes(scene);
    ASSERT_EQ(scene.meshes.size(), 2u);
    ASSERT_EQ(scene.materials.size(), 2u);  // the default and `lamp`
    int lamp = -1, floor = -1;
    for (int i = 0; i < 2; ++i)
        (scene.materials[size_t(scene.meshes[size_t(i)].material)].name == "lamp" ? lamp : floor) =
            i;
    ASSERT_GE(lamp, 0);
    ASSERT_GE(floor, 0);
    const Material& l = scene.materials[size_t(scene.meshes[size_t(lamp)].material)];
    expect_vec_near(l.base_color, Vec3(0.1f, 0.2f, 0.3f));
    expect_vec_near(l.emission(), Vec3(5, 4, 3));
    const Material& f = scene.materials[size_t(scene.meshes[size_t(floor)].material)];
    expect_vec_near(f.base_color, Vec3(0.5f));
    EXPECT_FALSE(f.is_emissive());
    // The lamp's corners share `vn 0 -1 0`: welded to four vertices with that normal.
    const Mesh& lm = scene.meshes[size_t(lamp)];
    EXPECT_EQ(lm.positions.size(), 4u);
    EXPECT_EQ(lm.triangle_count(), 2u);
    for (const Vec3& n : lm.normals)
        expect_vec_near(n, Vec3(0, -1, 0));
    EXPECT_EQ(scene.meshes[size_t(floor)].triangle_count(), 2u);
}

// What each malformed mesh's message must say (beyond starting with the path, on one line).
struct BadCase {
    const char* file;
    const char* expected;
};
const BadCase kBadCases[] = {
    {"ply-truncated-binary.ply", "truncated binary PLY"},
    {"ply-index-out-of-range.ply", "face 0 refers to vertex 3 of 3"},
    {"ply-negative-index.ply", "refers to vertex -1"},
    {"ply-bad-magic.ply", "does not start with 'ply'"},
    {"ply-unknown-format.ply", "unknown format 'binary_middle_endian'"},
    {"ply-unknown-type.ply", "bad property"},
    {"ply-no-end-header.ply", "no end_header"},
    {"ply-nan-vertex.ply", "vertex 1 has a non-finite position"},
    {"ply-inf-vertex-binary.ply", "vertex 1 has a non-finite position"},
    {"ply-huge-count.ply", "declares 4000000000 entries"},
    {"ply-two-vertex-face.ply", "face 0 has 2 vertices"},
    {"ply-point-cloud.ply", "no faces"},
    {"ply-bad-number.ply", "bad number 'zero'"},
    {"ply-no-xyz.ply", "no x, y and z"},
    {"ply-empty.ply", "file is empty"},
    {"obj-index-out-of-range.obj", "refers to vertex 4 of 3"},
    {"obj-two-vertex-face.obj", "a face has fewer than 3 vertices"},
    {"obj-no-faces.obj", "no triangle geometry"},
    {"obj-inf-vertex.obj", "vertex 2 has a non-finite position"},
    {"obj-empty.obj", "no triangle geometry"},
};

TEST(MeshLoaders, MalformedFilesAreOneLineInputErrors) {
    for (const BadCase& c : kBadCases) {
        const std::string path = bad_file(c.file);
        SCOPED_TRACE(path);
        try {
            const Scene scene = load_scene(path);
            ADD_FAILURE() << "loaded " << scene.triangle_count() << " triangles";
        } catch (const InputError& e) {
            const std::string message = e.what();
            EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
            EXPECT_EQ(message.find_first_of("\r\n"), std::string::npos) << message;
            EXPECT_NE(message.find(c.expected), std::string::npos)
                << "expected '" << c.expected << "' in: " << message;
        }
    }
}

TEST(MeshLoaders, MissingFileIsAnInputError) {
    EXPECT_THROW(load_scene(mesh_file("does-not-exist.ply")), InputError);
    EXPECT_THROW(load_scene(mesh_file("does-not-exist.obj")), InputError);
}

}  // namespace
}  // namespace mvpl::scene
