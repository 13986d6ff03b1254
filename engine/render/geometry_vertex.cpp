#include "engine/render/geometry_vertex.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <cstring>

namespace mvpl::render {

IndexedTriangles index_triangles(std::span<const GeometryVertex> corners) {
    IndexedTriangles out;
    const size_t n = corners.size() - corners.size() % 3;
    if (n == 0) return out;
    // Welded on every byte but the face normal, which only the provoking vertex passes on.
    std::vector<GeometryVertex> keyed(corners.begin(), corners.begin() + std::ptrdiff_t(n));
    for (GeometryVertex& v : keyed)
        std::fill(std::begin(v.face_normal), std::end(v.face_normal), 0.0f);
    out.indices.resize(n);
    const size_t unique = meshopt_generateVertexRemap(out.indices.data(), nullptr, n, keyed.data(),
                                                      n, sizeof(GeometryVertex));
    out.vertices.resize(unique);
    meshopt_remapVertexBuffer(out.vertices.data(), keyed.data(), n, sizeof(GeometryVertex),
                              out.indices.data());
    std::vector<bool> starts(unique, false);
    for (size_t t = 0; t < n; t += 3) {
        uint32_t* tri = &out.indices[t];
        int first = -1;
        for (int k = 0; k < 3 && first < 0; ++k) {
            if (!starts[tri[k]]) first = k;
        }
        if (first < 0) {
            out.vertices.push_back(out.vertices[tri[0]]);
            tri[0] = uint32_t(out.vertices.size() - 1);
            starts.push_back(false);
            first = 0;
        }
        // A rotation keeps the winding.
        std::rotate(tri, tri + first, tri + 3);
        starts[tri[0]] = true;
        std::memcpy(out.vertices[tri[0]].face_normal, corners[t].face_normal,
                    sizeof(corners[t].face_normal));
    }
    return out;
}

}  // namespace mvpl::render
