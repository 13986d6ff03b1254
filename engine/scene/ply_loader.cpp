#include "engine/scene/ply_loader.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "engine/core/error.h"
#include "engine/core/regular_file.h"
#include "engine/scene/mesh_limits.h"
#include "engine/scene/ply_format.h"
#include "engine/scene/scene_loader.h"
#include "engine/scene/scene_range.h"

namespace mvpl::scene {

namespace {

using ply::Element;
using ply::Format;
using ply::Header;
using ply::Property;
using ply::Reader;
using ply::type_size;

// Bounds that keep a hostile header from asking for absurd allocations (mesh_limits.h).
constexpr uint64_t kMaxPolygonVertices = uint64_t(1) << 16;

int property_index(const Element& e, const char* name) {
    for (size_t i = 0; i < e.properties.size(); ++i) {
        if (e.properties[i].name == name && !e.properties[i].is_list) return int(i);
    }
    return -1;
}

// Every value takes at least one byte (binary) or two characters (ascii, with its separator): a
// count the rest of the file cannot hold is refused before allocating.
void check_element_fits(const std::string& path, const Element& e, Format format,
                        size_t remaining) {
    size_t min_bytes = 0;
    for (const Property& p : e.properties)
        min_bytes += p.is_list ? type_size(p.count_type) : type_size(p.type);
    if (format == Format::ascii) min_bytes = 2 * e.properties.size();
    if (min_bytes > 0 && e.count > remaining / min_bytes) {
        throw InputError(path, "truncated PLY: element '" + e.name + "' declares " +
                                   std::to_string(e.count) + " entries, more than the " +
                                   std::to_string(remaining) + " bytes after the header hold");
    }
}

// The properties of the vertex element that make a mesh vertex (-1: absent).
struct VertexColumns {
    int xyz[3] = {-1, -1, -1};
    int nxyz[3] = {-1, -1, -1};
    int uv[2] = {-1, -1};
    bool normals = false;  // nx, ny and nz all present
};

VertexColumns vertex_columns(const std::string& path, const Element& e) {
    VertexColumns c;
    const char* names[6] = {"x", "y", "z", "nx", "ny", "nz"};
    for (int i = 0; i < 3; ++i) {
        c.xyz[i] = property_index(e, names[i]);
        c.nxyz[i] = property_index(e, names[3 + i]);
    }
    if (c.xyz[0] < 0 || c.xyz[1] < 0 || c.xyz[2] < 0)
        throw InputError(path, "the vertex element has no x, y and z properties");
    c.normals = c.nxyz[0] >= 0 && c.nxyz[1] >= 0 && c.nxyz[2] >= 0;
    // Texture coordinates under the names Mitsuba's PLY reader accepts.
    const char* uv_names[4][2] = {
        {"u", "v"}, {"s", "t"}, {"texture_u", "texture_v"}, {"texture_s", "texture_t"}};
    for (const auto& pair : uv_names) {
        if (c.uv[0] >= 0) break;
        c.uv[0] = property_index(e, pair[0]);
        c.uv[1] = property_index(e, pair[1]);
        if (c.uv[1] < 0) c.uv[0] = -1;
    }
    return c;
}

// The face element's vertex index list.
int face_list_column(const std::string& path, const Element& e) {
    int list = -1;
    for (size_t i = 0; i < e.properties.size(); ++i) {
        const Property& p = e.properties[i];
        if (p.is_list && (p.name == "vertex_indices" || p.name == "vertex_index")) list = int(i);
    }
    if (list < 0) throw InputError(path, "the face element has no vertex_indices list");
    return list;
}

// Entry n of element e: its scalar properties into `values`, the items of property `list` into
// `polygon` (checked as indices of `vertex_count` vertices); other lists are read and dropped.
void read_entry(Reader& reader, const std::string& path, const Element& e, uint64_t n, int list,
                size_t vertex_count, std::vector<double>& values, std::vector<uint32_t>& polygon) {
    for (size_t i = 0; i < e.properties.size(); ++i) {
        const Property& p = e.properties[i];
        if (!p.is_list) {
            values[i] = reader.read(p.type, p.name.c_str());
            continue;
        }
        const double count = reader.read(p.count_type, p.name.c_str());
        if (!(count >= 0.0 && count <= double(kMaxPolygonVertices)) || count != std::floor(count)) {
            throw InputError(path, "bad list length " + std::to_string(count) + " in " + e.name +
                                       " " + std::to_string(n));
        }
        if (int(i) == list) polygon.clear();
        for (uint64_t k = 0; k < uint64_t(count); ++k) {
            const double v = reader.read(p.type, p.name.c_str());
            if (int(i) != list) continue;
            if (!(v >= 0.0 && v < double(vertex_count)) || v != std::floor(v)) {
                throw InputError(path, "face " + std::to_string(n) + " refers to vertex " +
                                           std::to_string(int64_t(v)) + " of " +
                                           std::to_string(vertex_count));
            }
            polygon.push_back(uint32_t(v));
        }
    }
}

// Vertex n of the mesh from its element's `values`, checked finite and within range.
void store_vertex(const std::string& path, uint64_t n, const std::vector<double>& values,
                  const VertexColumns& c, Mesh& mesh) {
    const Vec3 p = Vec3(float(values[size_t(c.xyz[0])]), float(values[size_t(c.xyz[1])]),
                        float(values[size_t(c.xyz[2])]));
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
        throw InputError(path, "vertex " + std::to_string(n) +
                                   " has a non-finite position (NaN, infinity or "
                                   "beyond float range)");
    }
    for (int i = 0; i < 3; ++i) {
        // scene_range.h: what Embree and the shaders can carry.
        const double x = values[size_t(c.xyz[i])];
        if (std::abs(x) > kMaxCoordinate) {
            throw InputError(path, "vertex " + std::to_string(n) + " has " +
                                       std::string(1, "xyz"[i]) + " = " + number_text(x) +
                                       ", beyond the supported magnitude " +
                                       number_text(kMaxCoordinate));
        }
    }
    mesh.positions[n] = p;
    if (c.uv[0] >= 0) {
        mesh.uv0[n] = Vec2(float(values[size_t(c.uv[0])]), float(values[size_t(c.uv[1])]));
        if (!std::isfinite(mesh.uv0[n].x) || !std::isfinite(mesh.uv0[n].y))
            throw InputError(path,
                             "vertex " + std::to_string(n) + " has non-finite texture coordinates");
    }
    if (c.normals) {
        mesh.normals[n] = Vec3(float(values[size_t(c.nxyz[0])]), float(values[size_t(c.nxyz[1])]),
                               float(values[size_t(c.nxyz[2])]));
    }
}

// Face n (`polygon`, vertex indices) as triangles.
void add_face(const std::string& path, uint64_t n, const std::vector<uint32_t>& polygon,
              Mesh& mesh) {
    if (polygon.size() < 3) {
        throw InputError(path, "face " + std::to_string(n) + " has " +
                                   std::to_string(polygon.size()) +
                                   " vertices; a face needs at least 3");
    }
    // Fan triangulation: (0, k, k+1), which keeps the polygon's winding.
    for (size_t k = 1; k + 1 < polygon.size(); ++k)
        mesh.indices.insert(mesh.indices.end(), {polygon[0], uint32_t(polygon[k]), polygon[k + 1]});
    if (mesh.indices.size() / 3 > kMaxMeshTriangles)
        throw InputError(path, "more than 2^28 triangles");
}

}  // namespace

Mesh read_ply_mesh(const std::string& path) {
    require_regular_file(path);
    std::ifstream file(path, std::ios::binary);
    if (!file) throw InputError(path, "cannot open the file");
    const std::string data((std::istreambuf_iterator<char>(file)),
                           std::istreambuf_iterator<char>());
    const Header header = ply::parse_header(path, data);
    Reader reader(path, data, header.data_offset, header.format);

    Mesh mesh;
    mesh.name = std::filesystem::path(path).stem().string();
    bool have_vertices = false, have_faces = false;
    for (const Element& e : header.elements) {
        check_element_fits(path, e, header.format, reader.remaining());
        const bool is_vertex = e.name == "vertex" && !have_vertices;
        const bool is_face = e.name == "face" && !have_faces;
        VertexColumns columns;
        int list = -1;
        if (is_vertex) {
            columns = vertex_columns(path, e);
            mesh.positions.resize(e.count);
            if (columns.normals) mesh.normals.resize(e.count);
            if (columns.uv[0] >= 0) mesh.uv0.resize(e.count);
        }
        if (is_face) list = face_list_column(path, e);
        std::vector<double> values(e.properties.size());
        std::vector<uint32_t> polygon;
        for (uint64_t n = 0; n < e.count; ++n) {
            read_entry(reader, path, e, n, list, mesh.positions.size(), values, polygon);
            if (is_vertex) store_vertex(path, n, values, columns, mesh);
            if (is_face) add_face(path, n, polygon, mesh);
        }
        have_vertices = have_vertices || is_vertex;
        have_faces = have_faces || is_face;
    }
    if (!have_vertices) throw InputError(path, "no vertex element");
    if (mesh.indices.empty()) throw InputError(path, "no faces: a point cloud has no triangles");
    return mesh;
}

Scene load_ply(const std::string& path) {
    Mesh mesh = read_ply_mesh(path);
    mesh.uv0.clear();  // a bare mesh gets an untextured material
    std::vector<Mesh> meshes;
    meshes.push_back(std::move(mesh));
    return mesh_scene(path, std::move(meshes), {default_mesh_material()});
}

}  // namespace mvpl::scene
