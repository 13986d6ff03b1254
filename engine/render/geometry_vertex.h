#pragma once
// The vertex that the G-buffer (and the shadow maps' alpha-tested draws) read, and how a mesh's
// triangles become an indexed mesh of them.
//
// The G-buffer needs each triangle's winding normal, a per-triangle attribute. It is a `flat`
// input, which Vulkan takes from the triangle's first vertex (the provoking vertex): where no
// two triangles start with the same vertex, that vertex can carry its triangle's normal while
// the vertices the triangles share are fetched and shaded once. De-indexed (three vertices a
// triangle), the dragon's G-buffer shaded 607 k vertices for 202 k triangles on lavapipe.
#include <cstdint>
#include <span>
#include <vector>

namespace mvpl::render {

// One vertex as the passes read it (locations 0 to 5).
struct GeometryVertex {
    float position[3];
    float normal[3];       // interpolated vertex normal (the shading normal)
    float face_normal[3];  // the winding normal of the triangle this vertex starts (flat)
    float uv[4];           // TEXCOORD_0, TEXCOORD_1 (0 where the mesh has none)
    // As trace::make_interaction: TANGENT.xyz, else the triangle's ∂p/∂u from TEXCOORD_0, else
    // 0 (the fragment shader orthonormalises it); w = the tangent sign of the first vertex.
    float tangent[4];
    float color[4];  // COLOR_0 (linear RGBA), white where the mesh has none
};
static_assert(sizeof(GeometryVertex) == 84);

struct IndexedTriangles {
    std::vector<GeometryVertex> vertices;
    std::vector<uint32_t> indices;  // three per triangle, in the corners' order and winding
};

// corners: three per triangle, each with its triangle's winding normal. Corners equal in
// everything but the face normal become one vertex; triangle t keeps its corners' attributes,
// winding and order, its indices rotated so that its first vertex is one no other triangle
// starts with, holding corners[3t].face_normal (a copy of a vertex where all three are taken:
// about one vertex per triangle on a closed mesh, against three de-indexed).
IndexedTriangles index_triangles(std::span<const GeometryVertex> corners);

}  // namespace mvpl::render
