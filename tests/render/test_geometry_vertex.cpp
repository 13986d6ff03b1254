// index_triangles (engine/render/geometry_vertex.h): the G-buffer's indexed mesh must draw the
// same triangles with the same attributes as the de-indexed corners, each triangle's winding
// normal in a first vertex of its own (Vulkan's provoking vertex feeds the flat input).
#include <gtest/gtest.h>

#include <cstring>
#include <set>

#include "engine/render/geometry_vertex.h"
#include "tests/support/scene_builder.h"

namespace mvpl::render {
namespace {

void store3(float* out, const Vec3& v) {
    out[0] = v.x;
    out[1] = v.y;
    out[2] = v.z;
}

// The corners as SceneGeometry makes them: position, vertex normal, the triangle's winding
// normal; uv.x = the triangle's parity where `seams` (so that neighbours differ in uv).
std::vector<GeometryVertex> corners_of(const scene::Mesh& mesh, bool seams) {
    std::vector<GeometryVertex> corners;
    for (size_t t = 0; t < mesh.triangle_count(); ++t) {
        const uint32_t* idx = &mesh.indices[3 * t];
        const Vec3 face =
            glm::normalize(glm::cross(mesh.positions[idx[1]] - mesh.positions[idx[0]],
                                      mesh.positions[idx[2]] - mesh.positions[idx[0]]));
        for (int k = 0; k < 3; ++k) {
            GeometryVertex v{};
            store3(v.position, mesh.positions[idx[k]]);
            store3(v.normal, mesh.normals[idx[k]]);
            store3(v.face_normal, face);
            v.uv[0] = seams ? float(t % 2) : 0.0f;
            v.color[0] = v.color[1] = v.color[2] = v.color[3] = 1.0f;
            corners.push_back(v);
        }
    }
    return corners;
}

bool same_except_face(const GeometryVertex& a, const GeometryVertex& b) {
    GeometryVertex x = a;
    GeometryVertex y = b;
    std::memset(x.face_normal, 0, sizeof(x.face_normal));
    std::memset(y.face_normal, 0, sizeof(y.face_normal));
    return std::memcmp(&x, &y, sizeof(GeometryVertex)) == 0;
}

// Triangle t of `out` is corners t with its corners in the same cyclic order (a rotation keeps
// the winding), its first vertex holding corners[3t]'s face normal, and no other triangle starts
// with that vertex.
void expect_same_triangles(const std::vector<GeometryVertex>& corners,
                           const IndexedTriangles& out) {
    ASSERT_EQ(out.indices.size(), corners.size());
    std::set<uint32_t> firsts;
    for (size_t t = 0; t < corners.size(); t += 3) {
        const uint32_t* tri = &out.indices[t];
        for (int k = 0; k < 3; ++k)
            ASSERT_LT(tri[k], out.vertices.size());
        int rotation = -1;
        for (int r = 0; r < 3 && rotation < 0; ++r) {
            bool all = true;
            for (int k = 0; k < 3; ++k)
                all = all && same_except_face(out.vertices[tri[k]], corners[t + (k + r) % 3]);
            if (all) rotation = r;
        }
        EXPECT_GE(rotation, 0) << "triangle " << t / 3 << " lost its corners or its winding";
        EXPECT_EQ(std::memcmp(out.vertices[tri[0]].face_normal, corners[t].face_normal,
                              sizeof(corners[t].face_normal)),
                  0)
            << "triangle " << t / 3;
        EXPECT_TRUE(firsts.insert(tri[0]).second) << "triangle " << t / 3 << " shares its first";
    }
}

TEST(IndexTriangles, AClosedMeshKeepsEveryTriangleWithAboutOneVertexEach) {
    // 1280 triangles on 642 shared vertices.
    const scene::Mesh sphere = test::make_icosphere(Vec3(0.0f), 1.0f, 3, false, 0);
    const std::vector<GeometryVertex> corners = corners_of(sphere, false);
    const IndexedTriangles out = index_triangles(corners);
    expect_same_triangles(corners, out);
    // Each triangle needs a first vertex of its own: at least one vertex a triangle, and the
    // shared ones are not copied where a triangle can start with one no other took.
    const size_t triangles = sphere.triangle_count();
    EXPECT_GE(out.vertices.size(), triangles);
    EXPECT_LE(out.vertices.size(), triangles + triangles / 4) << "de-indexed: " << corners.size();
}

TEST(IndexTriangles, CornersThatDifferInAnAttributeStayApart) {
    const scene::Mesh sphere = test::make_icosphere(Vec3(0.0f), 1.0f, 2, false, 0);
    const std::vector<GeometryVertex> corners = corners_of(sphere, true);
    const IndexedTriangles out = index_triangles(corners);
    expect_same_triangles(corners, out);
}

TEST(IndexTriangles, NoCornersNoTriangles) {
    const IndexedTriangles out = index_triangles({});
    EXPECT_TRUE(out.vertices.empty());
    EXPECT_TRUE(out.indices.empty());
}

}  // namespace
}  // namespace mvpl::render
