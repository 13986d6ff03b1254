#include "engine/scene/gltf_geometry.h"

#include <numeric>
#include <optional>
#include <utility>

#include "engine/scene/gltf_accessor.h"
#include "engine/scene/gltf_value.h"
#include "engine/scene/mesh_limits.h"
#include "engine/scene/scene_range.h"

namespace mvpl::scene::gltf {
namespace {

using DMat3 = glm::dmat3;

// Any unit vector will do for a degenerate triangle: it has no area to shade.
const Vec3 kFallbackNormal(0.0f, 0.0f, 1.0f);

std::optional<int> attribute(const tinygltf::Primitive& primitive, const char* name) {
    const auto it = primitive.attributes.find(name);
    if (it == primitive.attributes.end()) return std::nullopt;
    return it->second;
}

// Every component finite and, where `limit` is given, of magnitude at most `limit`.
template <typename V>
void check_finite(const Document& doc, const std::vector<V>& values, const AccessorView& view,
                  std::optional<double> limit = std::nullopt) {
    for (size_t i = 0; i < values.size(); ++i) {
        for (int c = 0; c < V::length(); ++c) {
            if (!std::isfinite(values[i][c])) {
                doc.fail(view.label() + " has a non-finite value at element " + std::to_string(i));
            }
            if (limit && std::abs(values[i][c]) > *limit) {
                doc.fail(
                    indexed(indexed(indexed("accessors", size_t(view.index())), i), size_t(c)) +
                    " (" + view.usage() + ") is " + number_text(values[i][c]) +
                    ", beyond the supported magnitude " + number_text(*limit));
            }
        }
    }
}

// glTF's strip and fan orders (spec 3.7.2.1), which keep every triangle's winding.
std::vector<uint32_t> triangulate(int mode, const std::vector<uint32_t>& corners,
                                  size_t triangle_count) {
    if (mode == TINYGLTF_MODE_TRIANGLES) return corners;
    std::vector<uint32_t> triangles;
    triangles.reserve(3 * triangle_count);
    for (size_t i = 0; i < triangle_count; ++i) {
        if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
            const size_t odd = i % 2;
            triangles.insert(triangles.end(),
                             {corners[i], corners[i + 1 + odd], corners[i + 2 - odd]});
        } else {
            triangles.insert(triangles.end(), {corners[i + 1], corners[i + 2], corners[0]});
        }
    }
    return triangles;
}

// Twice the triangle's area along its normal, in double so that tiny triangles do not underflow.
DVec3 face_normal(const std::vector<Vec3>& p, const uint32_t* tri) {
    const DVec3 a(p[tri[0]]);
    return glm::cross(DVec3(p[tri[1]]) - a, DVec3(p[tri[2]]) - a);
}

Vec3 unit_or_fallback(const DVec3& v) {
    const double length = glm::length(v);
    return length > 0.0 && std::isfinite(length) ? Vec3(v / length) : kFallbackNormal;
}

// A node's world transform applied in double. Normals go through the cofactor matrix (the
// inverse transpose scaled by the determinant, sign kept positive) so that a singular transform
// needs no division; a mirroring transform must reverse the winding so that the front face stays
// the front face.
class Placement {
public:
    explicit Placement(const DMat4& world)
        : m_world(world), m_linear(world), m_det(glm::determinant(m_linear)) {
        m_normal = DMat3(glm::cross(m_linear[1], m_linear[2]), glm::cross(m_linear[2], m_linear[0]),
                         glm::cross(m_linear[0], m_linear[1]));
        if (mirrors()) m_normal = -m_normal;
    }

    bool mirrors() const { return m_det < 0.0; }
    DVec3 point(const Vec3& p) const { return DVec3(m_world * glm::dvec4(DVec3(p), 1.0)); }
    // Unnormalised; zero where the transform collapses the normal.
    DVec3 normal(const Vec3& n) const { return m_normal * DVec3(n); }
    // Direction through the linear part; handedness flips with a mirror.
    Vec4 tangent(const Vec4& t) const {
        const DVec3 d = m_linear * DVec3(t);
        const double length = glm::length(d);
        const Vec3 xyz = length > 0.0 && std::isfinite(length) ? Vec3(d / length) : Vec3(0.0f);
        return Vec4(xyz, mirrors() ? -t.w : t.w);
    }

private:
    DMat4 m_world;
    DMat3 m_linear;
    double m_det;
    DMat3 m_normal;
};

// The file's normals placed in the world; a normal that is zero (in the file or after the
// transform) takes the area-weighted normal of the triangles around its vertex.
std::vector<Vec3> placed_normals(const Placement& placement, const std::vector<Vec3>& normals,
                                 const std::vector<Vec3>& positions,
                                 const std::vector<uint32_t>& triangles) {
    std::vector<Vec3> out(normals.size(), Vec3(0.0f));
    bool any_unusable = false;
    for (size_t i = 0; i < normals.size(); ++i) {
        const DVec3 n = placement.normal(normals[i]);
        const double length = glm::length(n);
        if (length > 0.0 && std::isfinite(length)) {
            out[i] = Vec3(n / length);
        } else {
            any_unusable = true;
        }
    }
    if (!any_unusable) return out;
    std::vector<DVec3> sums(normals.size(), DVec3(0.0));
    for (size_t t = 0; t < triangles.size(); t += 3) {
        const DVec3 n = face_normal(positions, &triangles[t]);
        for (size_t c = t; c < t + 3; ++c)
            sums[triangles[c]] += n;
    }
    for (size_t i = 0; i < out.size(); ++i) {
        if (out[i] == Vec3(0.0f)) out[i] = unit_or_fallback(sums[i]);
    }
    return out;
}

// The file's vertex data, before placement.
struct Attributes {
    std::vector<Vec3> normals;
    std::vector<Vec2> uv0;
    std::vector<Vec2> uv1;
    std::vector<Vec4> tangents;
    std::vector<Vec4> colors;
};

Attributes read_attributes(const Document& doc, const tinygltf::Primitive& primitive,
                           const std::string& where, size_t vertex_count) {
    auto view = [&](const char* name, int type, std::vector<int> component_types,
                    bool normalized) -> std::optional<AccessorView> {
        const std::optional<int> index = attribute(primitive, name);
        if (!index) return std::nullopt;
        AccessorView v(doc, *index,
                       AccessorNeeds{std::string(name) + " of " + where, type,
                                     std::move(component_types), normalized});
        if (v.count() != vertex_count) {
            doc.fail(v.label() + " has " + std::to_string(v.count()) +
                     " elements but POSITION has " + std::to_string(vertex_count));
        }
        return v;
    };
    constexpr int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;
    const std::vector<int> texcoord_types = {kFloat, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                             TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT};
    Attributes out;
    if (auto v = view("NORMAL", TINYGLTF_TYPE_VEC3, {kFloat}, false)) {
        out.normals = v->read_vec3();
        check_finite(doc, out.normals, *v);
    }
    if (auto v = view("TEXCOORD_0", TINYGLTF_TYPE_VEC2, texcoord_types, true)) {
        out.uv0 = v->read_vec2();
        check_finite(doc, out.uv0, *v, kMaxFactor);
    }
    if (auto v = view("TEXCOORD_1", TINYGLTF_TYPE_VEC2, texcoord_types, true)) {
        out.uv1 = v->read_vec2();
        check_finite(doc, out.uv1, *v, kMaxFactor);
    }
    if (auto v = view("TANGENT", TINYGLTF_TYPE_VEC4, {kFloat}, false)) {
        out.tangents = v->read_vec4();
        check_finite(doc, out.tangents, *v);
    }
    // COLOR_0: VEC3 or VEC4 of float or normalized unsigned byte/short; alpha 1 for VEC3.
    if (const std::optional<int> index = attribute(primitive, "COLOR_0")) {
        const bool rgb = *index >= 0 && size_t(*index) < doc.model.accessors.size() &&
                         doc.model.accessors[size_t(*index)].type == TINYGLTF_TYPE_VEC3;
        if (auto v = view("COLOR_0", rgb ? TINYGLTF_TYPE_VEC3 : TINYGLTF_TYPE_VEC4, texcoord_types,
                          true)) {
            if (rgb) {
                for (const Vec3& c : v->read_vec3())
                    out.colors.emplace_back(c, 1.0f);
            } else {
                out.colors = v->read_vec4();
            }
            check_finite(doc, out.colors, *v, kMaxFactor);
        }
    }
    return out;
}

template <typename T>
std::vector<T> unweld(const std::vector<T>& values, const std::vector<uint32_t>& triangles) {
    if (values.empty()) return {};
    std::vector<T> out(triangles.size());
    for (size_t i = 0; i < triangles.size(); ++i)
        out[i] = values[triangles[i]];
    return out;
}

// The primitive's index accessor, if it has one.
std::optional<AccessorView> indices_accessor(const Document& doc,
                                             const tinygltf::Primitive& primitive,
                                             const std::string& where) {
    std::optional<AccessorView> indices_view;
    if (primitive.indices != -1) {
        indices_view.emplace(doc, primitive.indices,
                             AccessorNeeds{"indices of " + where,
                                           TINYGLTF_TYPE_SCALAR,
                                           {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                            TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                            TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT}});
    }
    return indices_view;
}

// The triangles that `corner_count` corners (indices when `indexed`, else vertices) make in
// `mode`.
size_t count_triangles(const Document& doc, const std::string& where, int mode, size_t corner_count,
                       bool indexed) {
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        if (corner_count % 3 != 0) {
            doc.fail(where + " has " + std::to_string(corner_count) +
                     (indexed ? " indices" : " vertices") + ", not a multiple of 3");
        }
        return corner_count / 3;
    }
    return corner_count >= 3 ? corner_count - 2 : 0;
}

// Charges a placed primitive's triangles and output vertices to the scene's budget.
void charge(const Document& doc, GeometryBudget& budget, size_t triangle_count,
            uint64_t out_vertices, const std::string& placed) {
    if (budget.triangles + triangle_count > kMaxMeshTriangles) {
        doc.fail("the scene has more than " + std::to_string(kMaxMeshTriangles) +
                 " triangles when " + placed);
    }
    if (budget.vertices + out_vertices > kMaxMeshVertices) {
        doc.fail("the scene has more than " + std::to_string(kMaxMeshVertices) + " vertices when " +
                 placed);
    }
    budget.triangles += triangle_count;
    budget.vertices += out_vertices;
}

// The primitive's corners as vertex indices: its indices (checked), else every vertex in order.
std::vector<uint32_t> read_corners(const Document& doc,
                                   const std::optional<AccessorView>& indices_view,
                                   size_t vertex_count) {
    std::vector<uint32_t> corners;
    if (indices_view) {
        corners = indices_view->read_uints();
        for (size_t i = 0; i < corners.size(); ++i) {
            if (corners[i] >= vertex_count) {
                doc.fail(indices_view->label() + " has index " + std::to_string(corners[i]) +
                         " at element " + std::to_string(i) + ", past the vertex count " +
                         std::to_string(vertex_count));
            }
        }
    } else {
        corners.resize(vertex_count);
        std::iota(corners.begin(), corners.end(), 0u);
    }
    return corners;
}

// The positions placed in the world by node `node`, each within scene_range.h's bounds.
void place_positions(const Document& doc, const Placement& placement, int node,
                     const AccessorView& positions_view, std::vector<Vec3>& positions) {
    for (size_t i = 0; i < positions.size(); ++i) {
        const DVec3 p = placement.point(positions[i]);
        for (int c = 0; c < 3; ++c) {
            if (!(std::abs(p[c]) <= kMaxCoordinate)) {
                doc.fail(indexed("nodes", size_t(node)) + " places " +
                         indexed(indexed("accessors", size_t(positions_view.index())), i) + " (" +
                         positions_view.usage() + ") at " + std::string(1, "xyz"[c]) + " = " +
                         number_text(p[c]) + ", beyond the supported magnitude " +
                         number_text(kMaxCoordinate));
            }
        }
        positions[i] = Vec3(p);
    }
}

// glTF: without normals the primitive is flat shaded, so every triangle gets its own three
// vertices carrying its face normal.
void flat_shaded(const std::vector<Vec3>& positions, const std::vector<uint32_t>& triangles,
                 const Attributes& attributes, Mesh& out) {
    out.positions = unweld(positions, triangles);
    out.uv0 = unweld(attributes.uv0, triangles);
    out.uv1 = unweld(attributes.uv1, triangles);
    out.tangents = unweld(attributes.tangents, triangles);
    out.colors = unweld(attributes.colors, triangles);
    out.normals.resize(out.positions.size());
    out.indices.resize(out.positions.size());
    std::iota(out.indices.begin(), out.indices.end(), 0u);
    for (size_t t = 0; t < out.indices.size(); t += 3) {
        const Vec3 n = unit_or_fallback(face_normal(out.positions, &out.indices[t]));
        out.normals[t] = out.normals[t + 1] = out.normals[t + 2] = n;
    }
}

}  // namespace

bool build_primitive_mesh(const Document& doc, int mesh_index, int primitive_index, int node,
                          const DMat4& world, GeometryBudget& budget, Mesh& out) {
    const tinygltf::Mesh& mesh = doc.model.meshes[size_t(mesh_index)];
    const tinygltf::Primitive& primitive = mesh.primitives[size_t(primitive_index)];
    const std::string where =
        "mesh " + std::to_string(mesh_index) + " primitive " + std::to_string(primitive_index);

    const int mode = primitive.mode == -1 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
    if (mode == TINYGLTF_MODE_POINTS || mode == TINYGLTF_MODE_LINE ||
        mode == TINYGLTF_MODE_LINE_LOOP || mode == TINYGLTF_MODE_LINE_STRIP) {
        return false;
    }
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        mode != TINYGLTF_MODE_TRIANGLE_FAN) {
        doc.fail(where + " has an invalid mode " + std::to_string(mode));
    }

    // Sizes first: everything below is charged to the budget before it is allocated.
    const std::optional<int> position_index = attribute(primitive, "POSITION");
    if (!position_index) doc.fail(where + " has no POSITION attribute");
    const AccessorView positions_view(
        doc, *position_index,
        AccessorNeeds{"POSITION of " + where, TINYGLTF_TYPE_VEC3, {TINYGLTF_COMPONENT_TYPE_FLOAT}});
    const size_t vertex_count = positions_view.count();
    const std::optional<AccessorView> indices_view = indices_accessor(doc, primitive, where);
    const size_t corner_count = indices_view ? indices_view->count() : vertex_count;
    const size_t triangle_count =
        count_triangles(doc, where, mode, corner_count, indices_view.has_value());
    if (triangle_count == 0) return false;
    const bool has_normals = attribute(primitive, "NORMAL").has_value();
    const uint64_t out_vertices = has_normals ? vertex_count : 3 * uint64_t(triangle_count);
    charge(doc, budget, triangle_count, out_vertices,
           "node " + std::to_string(node) + " places " + where);

    std::vector<Vec3> positions = positions_view.read_vec3();
    check_finite(doc, positions, positions_view);
    std::vector<uint32_t> triangles =
        triangulate(mode, read_corners(doc, indices_view, vertex_count), triangle_count);
    Attributes attributes = read_attributes(doc, primitive, where, vertex_count);

    const Placement placement(world);
    place_positions(doc, placement, node, positions_view, positions);
    if (placement.mirrors()) {
        for (size_t t = 0; t < triangles.size(); t += 3) {
            std::swap(triangles[t + 1], triangles[t + 2]);
        }
    }
    for (Vec4& tangent : attributes.tangents)
        tangent = placement.tangent(tangent);

    out.name = (mesh.name.empty() ? "mesh " + std::to_string(mesh_index) : mesh.name) +
               (mesh.primitives.size() > 1 ? " primitive " + std::to_string(primitive_index) : "");
    if (!has_normals) {
        flat_shaded(positions, triangles, attributes, out);
        return true;
    }
    out.normals = placed_normals(placement, attributes.normals, positions, triangles);
    out.positions = std::move(positions);
    out.uv0 = std::move(attributes.uv0);
    out.uv1 = std::move(attributes.uv1);
    out.tangents = std::move(attributes.tangents);
    out.colors = std::move(attributes.colors);
    out.indices = std::move(triangles);
    return true;
}

}  // namespace mvpl::scene::gltf
