#include "engine/scene/obj_loader.h"

#include <tiny_obj_loader.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <tuple>
#include <vector>

#include "engine/core/error.h"
#include "engine/core/regular_file.h"
#include "engine/scene/mesh_limits.h"
#include "engine/scene/scene_loader.h"
#include "engine/scene/scene_range.h"

namespace mvpl::scene {

namespace {

// tinyobjloader's messages may span lines; the first names the problem.
std::string first_line(const std::string& text) {
    std::string line = text.substr(0, text.find_first_of("\r\n"));
    return line.empty() ? "cannot parse the OBJ file" : line;
}

Rgb rgb(const tinyobj::real_t* v) {
    return Rgb(float(v[0]), float(v[1]), float(v[2]));
}

bool valid_colour(const Rgb& c) {
    for (int i = 0; i < 3; ++i) {
        if (!(c[i] >= 0.0f) || !std::isfinite(c[i])) return false;
    }
    return true;
}

// A corner's attribute references; equal keys share one output vertex.
using CornerKey = std::tuple<int, int, int>;

struct MeshBuilder {
    Mesh mesh;
    std::map<CornerKey, uint32_t> vertices;
    bool all_normals = true;
};

// Every position finite and within scene_range.h's bounds.
void check_positions(const std::string& path, const tinyobj::attrib_t& attrib) {
    const size_t vertex_count = attrib.vertices.size() / 3;
    for (size_t v = 0; v < vertex_count; ++v) {
        for (int c = 0; c < 3; ++c) {
            const double x = double(attrib.vertices[3 * v + size_t(c)]);
            if (!std::isfinite(float(x))) {
                throw InputError(path, "vertex " + std::to_string(v + 1) +
                                           " has a non-finite position (NaN, infinity or beyond "
                                           "float range)");
            }
            // scene_range.h: what Embree and the shaders can carry.
            if (std::abs(x) > kMaxCoordinate) {
                throw InputError(path, "vertex " + std::to_string(v + 1) + " has " +
                                           std::string(1, "xyz"[c]) + " = " + number_text(x) +
                                           ", beyond the supported magnitude " +
                                           number_text(kMaxCoordinate));
            }
        }
    }
}

// Scene material 0 is the default; .mtl material m is scene material m + 1.
std::vector<Material> scene_materials(const std::string& path,
                                      const std::vector<tinyobj::material_t>& mtl) {
    std::vector<Material> materials = {default_mesh_material()};
    for (const tinyobj::material_t& m : mtl) {
        Material out = default_mesh_material();
        out.name = m.name;
        out.base_color = rgb(m.diffuse);
        out.emissive = rgb(m.emission);
        if (!valid_colour(out.base_color) || !valid_colour(out.emissive)) {
            throw InputError(path,
                             "material '" + m.name + "' has a negative or non-finite Kd or Ke");
        }
        for (int c = 0; c < 3; ++c) {
            const double kd = double(m.diffuse[c]);
            const double ke = double(m.emission[c]);
            if (kd > kMaxFactor || ke > kMaxFactor) {
                throw InputError(path, "material '" + m.name + "' has " +
                                           (kd > kMaxFactor ? "Kd" : "Ke") + " " +
                                           number_text(std::max(kd, ke)) +
                                           ", beyond the supported " + number_text(kMaxFactor));
            }
        }
        materials.push_back(out);
    }
    return materials;
}

// The builder's vertex for corner `i` of face f of `shape`, added on its first use.
uint32_t corner_vertex(const std::string& path, const tinyobj::attrib_t& attrib,
                       const tinyobj::shape_t& shape, size_t f, const tinyobj::index_t& i,
                       MeshBuilder& b) {
    const size_t vertex_count = attrib.vertices.size() / 3;
    if (i.vertex_index < 0 || size_t(i.vertex_index) >= vertex_count) {
        throw InputError(path, "face " + std::to_string(f + 1) + " of '" + shape.name +
                                   "' refers to vertex " + std::to_string(i.vertex_index + 1) +
                                   " of " + std::to_string(vertex_count));
    }
    const bool has_normal =
        i.normal_index >= 0 && size_t(i.normal_index) < attrib.normals.size() / 3;
    b.all_normals = b.all_normals && has_normal;
    const CornerKey key(i.vertex_index, has_normal ? i.normal_index : -1, -1);
    auto [it, inserted] = b.vertices.try_emplace(key, uint32_t(b.mesh.positions.size()));
    if (inserted) {
        const size_t v = size_t(i.vertex_index);
        b.mesh.positions.emplace_back(float(attrib.vertices[3 * v]),
                                      float(attrib.vertices[3 * v + 1]),
                                      float(attrib.vertices[3 * v + 2]));
        const size_t nn = has_normal ? size_t(i.normal_index) : 0;
        b.mesh.normals.push_back(has_normal ? Vec3(float(attrib.normals[3 * nn]),
                                                   float(attrib.normals[3 * nn + 1]),
                                                   float(attrib.normals[3 * nn + 2]))
                                            : Vec3(0.0f));
    }
    return it->second;
}

// The faces of `shape`, fanned into triangles, each in the builder of its scene material;
// `triangles` counts them over all shapes.
void add_shape(const std::string& path, const tinyobj::ObjReader& reader,
               const tinyobj::shape_t& shape, const std::vector<Material>& materials,
               std::map<int, MeshBuilder>& builders, size_t& triangles) {
    const tinyobj::mesh_t& m = shape.mesh;
    const size_t mtl_count = reader.GetMaterials().size();
    size_t corner = 0;
    for (size_t f = 0; f < m.num_face_vertices.size(); ++f) {
        const size_t n = m.num_face_vertices[f];
        if (corner + n > m.indices.size()) throw InputError(path, "inconsistent face data");
        const int material_id = f < m.material_ids.size() ? m.material_ids[f] : -1;
        const int material =
            material_id >= 0 && size_t(material_id) < mtl_count ? material_id + 1 : 0;
        MeshBuilder& b = builders[material];
        if (b.mesh.name.empty()) b.mesh.name = materials[size_t(material)].name;
        b.mesh.material = material;
        std::vector<uint32_t> polygon;
        for (size_t k = 0; k < n; ++k)
            polygon.push_back(
                corner_vertex(path, reader.GetAttrib(), shape, f, m.indices[corner + k], b));
        corner += n;
        if (n < 3) {
            throw InputError(path, "face " + std::to_string(f + 1) + " of '" + shape.name +
                                       "' has " + std::to_string(n) +
                                       " vertices; a face needs at least 3");
        }
        // Fan triangulation (0, k, k+1), keeping the polygon's winding.
        for (size_t k = 1; k + 1 < n; ++k)
            b.mesh.indices.insert(b.mesh.indices.end(), {polygon[0], polygon[k], polygon[k + 1]});
        triangles += n - 2;
        if (triangles > kMaxMeshTriangles) throw InputError(path, "more than 2^28 triangles");
    }
}

}  // namespace

Scene load_obj(const std::string& path) {
    require_regular_file(path);
    tinyobj::ObjReaderConfig config;
    config.triangulate = false;  // fanned below, as PLY faces are
    config.vertex_color = false;
    config.mtl_search_path = std::filesystem::path(path).parent_path().string();
    tinyobj::ObjReader reader;
    if (!reader.ParseFromFile(path, config)) throw InputError(path, first_line(reader.Error()));
    // tinyobjloader drops faces of fewer than three corners with only a warning; a file that
    // silently loses geometry is refused instead.
    if (reader.Warning().find("Degenerated face") != std::string::npos)
        throw InputError(path, "a face has fewer than 3 vertices");
    check_positions(path, reader.GetAttrib());
    std::vector<Material> materials = scene_materials(path, reader.GetMaterials());

    std::map<int, MeshBuilder> builders;  // by scene material
    size_t triangles = 0;
    for (const tinyobj::shape_t& shape : reader.GetShapes())
        add_shape(path, reader, shape, materials, builders, triangles);
    std::vector<Mesh> meshes;
    for (auto& [material, b] : builders) {
        // A mesh whose corners do not all carry a normal is flat shaded (mesh_scene).
        if (!b.all_normals) b.mesh.normals.clear();
        meshes.push_back(std::move(b.mesh));
    }
    if (meshes.empty()) throw InputError(path, "no faces: no triangle geometry");
    return mesh_scene(path, std::move(meshes), std::move(materials));
}

}  // namespace mvpl::scene
