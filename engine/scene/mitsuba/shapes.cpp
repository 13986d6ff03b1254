#include "engine/scene/mitsuba/shapes.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

#include "engine/core/error.h"
#include "engine/scene/mitsuba/obj_mesh.h"
#include "engine/scene/mitsuba/primitives.h"
#include "engine/scene/mitsuba/properties.h"
#include "engine/scene/mitsuba/serialized_mesh.h"
#include "engine/scene/mitsuba/transform.h"
#include "engine/scene/ply_loader.h"
#include "engine/scene/scene_range.h"

namespace mvpl::scene::mitsuba {

namespace {

// Instances of instances nest no deeper than this (Mitsuba allows none; this bounds recursion).
constexpr int kMaxInstanceDepth = 8;

// Angle-weighted vertex normals (Thürmer & Wüthrich 1998), as Mitsuba's recompute_vertex_normals.
void smooth_normals(Mesh& m) {
    std::vector<DVec3> sum(m.positions.size(), DVec3(0.0));
    for (size_t t = 0; t < m.indices.size(); t += 3) {
        const uint32_t i[3] = {m.indices[t], m.indices[t + 1], m.indices[t + 2]};
        const DVec3 p[3] = {DVec3(m.positions[i[0]]), DVec3(m.positions[i[1]]),
                            DVec3(m.positions[i[2]])};
        const DVec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
        const double length = glm::length(n);
        if (!(length > 0.0)) continue;
        for (int k = 0; k < 3; ++k) {
            const DVec3 a = p[(k + 1) % 3] - p[k], b = p[(k + 2) % 3] - p[k];
            const double la = glm::length(a), lb = glm::length(b);
            if (!(la > 0.0 && lb > 0.0)) continue;
            const double angle = std::acos(std::clamp(glm::dot(a, b) / (la * lb), -1.0, 1.0));
            sum[i[k]] += n / length * angle;
        }
    }
    m.normals.resize(m.positions.size());
    for (size_t v = 0; v < sum.size(); ++v) {
        const double length = glm::length(sum[v]);
        m.normals[v] = length > 0.0 ? Vec3(sum[v] / length) : Vec3(0.0f, 0.0f, 1.0f);
    }
}

// Every triangle its own vertices with its face normal.
void flat_normals(Mesh& m) {
    Mesh flat;
    flat.name = m.name;
    for (size_t t = 0; t < m.indices.size(); t += 3) {
        const Vec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]],
                   c = m.positions[m.indices[t + 2]];
        const DVec3 n = glm::cross(DVec3(b) - DVec3(a), DVec3(c) - DVec3(a));
        const double length = glm::length(n);
        const Vec3 unit = length > 0.0 ? Vec3(n / length) : Vec3(0.0f, 0.0f, 1.0f);
        for (int k = 0; k < 3; ++k) {
            const uint32_t i = m.indices[t + size_t(k)];
            flat.positions.push_back(m.positions[i]);
            flat.normals.push_back(unit);
            if (!m.uv0.empty()) flat.uv0.push_back(m.uv0[i]);
            flat.indices.push_back(uint32_t(flat.indices.size()));
        }
    }
    m = std::move(flat);
}

// The shape's geometry in object space, and whether it asks for face normals.
Mesh object_mesh(Context& ctx, pugi::xml_node shape, DMat4& local) {
    const std::string type = shape.attribute("type").as_string();
    const bool from_file = type == "obj" || type == "ply" || type == "serialized";
    std::string path;
    if (from_file) {
        // Resolved outside the try below: a missing file is the XML's error, at its line.
        const pugi::xml_node name = ctx.property(shape, "filename");
        if (!name) ctx.fail(shape, "shape type '" + type + "' needs a filename");
        path = ctx.xml().resolve(name, name.attribute("value").as_string());
    }
    try {
        if (type == "obj") return read_obj_mesh(path, ctx.get_bool(shape, "flip_tex_coords", true));
        if (type == "ply") return read_ply_mesh(path);
        if (type == "serialized") {
            bool face = false;
            Mesh m = read_serialized_mesh(path, ctx.get_int(shape, "shape_index", 0), &face);
            if (face) m.normals.clear();
            return m;
        }
    } catch (const InputError& e) {
        // The mesh file's own message (it names the file) after the shape's line.
        ctx.fail(shape, e.what());
    }
    if (type == "rectangle") return rectangle_mesh();
    if (type == "cube") return cube_mesh();
    if (type == "disk") return disk_mesh();
    if (type == "sphere") {
        const float radius = ctx.get_float(shape, "radius", 1.0f);
        if (!(radius > 0.0f)) ctx.fail(shape, "sphere radius must be positive");
        const Vec3 center = ctx.get_point(shape, "center", Vec3(0.0f));
        local = glm::scale(glm::translate(DMat4(1.0), DVec3(center)), DVec3(radius));
        return sphere_mesh();
    }
    if (type == "cylinder") {
        const float radius = ctx.get_float(shape, "radius", 1.0f);
        if (!(radius > 0.0f)) ctx.fail(shape, "cylinder radius must be positive");
        const DVec3 p0(ctx.get_point(shape, "p0", Vec3(0.0f)));
        const DVec3 p1(ctx.get_point(shape, "p1", Vec3(0.0f, 0.0f, 1.0f)));
        const DVec3 axis = p1 - p0;
        if (!(glm::length(axis) > 0.0)) ctx.fail(shape, "cylinder p0 and p1 coincide");
        const DVec3 z = glm::normalize(axis);
        const DVec3 x = glm::normalize(std::abs(z.x) > 0.9 ? glm::cross(z, DVec3(0, 1, 0))
                                                           : glm::cross(z, DVec3(1, 0, 0)));
        const DVec3 y = glm::cross(z, x);
        local = DMat4(glm::dvec4(x * double(radius), 0.0), glm::dvec4(y * double(radius), 0.0),
                      glm::dvec4(axis, 0.0), glm::dvec4(p0, 1.0));
        return cylinder_mesh();
    }
    ctx.fail(shape, "shape type '" + type + "' is not supported");
}

void transform_mesh(Context& ctx, pugi::xml_node shape, Mesh& m, const DMat4& to_world) {
    const glm::dmat3 linear(to_world);
    const double det = glm::determinant(linear);
    if (!(std::abs(det) > 1e-30)) ctx.fail(shape, "the shape's to_world is singular");
    const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(linear));
    for (Vec3& p : m.positions) {
        const DVec3 w = DVec3(to_world * glm::dvec4(DVec3(p), 1.0));
        for (int c = 0; c < 3; ++c) {
            if (!(std::abs(w[c]) <= kMaxCoordinate))
                ctx.fail(shape, "a vertex lies at " + number_text(w[c]) +
                                    ", beyond the supported magnitude " +
                                    number_text(kMaxCoordinate));
        }
        p = Vec3(w);
    }
    for (Vec3& n : m.normals) {
        const DVec3 w = normal_matrix * DVec3(n);
        const double length = glm::length(w);
        n = length > 0.0 && std::isfinite(length) ? Vec3(w / length) : Vec3(0.0f, 0.0f, 1.0f);
    }
}

void add_shape_at(Context& ctx, pugi::xml_node shape, const DMat4& parent,
                  const MaterialOf& material_of, int depth) {
    const std::string type = shape.attribute("type").as_string();
    if (type == "shapegroup") return;  // drawn only through instances
    if (type == "instance") {
        if (depth >= kMaxInstanceDepth) ctx.fail(shape, "instances nest too deeply");
        const std::vector<pugi::xml_node> groups = ctx.objects(shape, "shape");
        if (groups.size() != 1 ||
            std::string(groups[0].attribute("type").as_string()) != "shapegroup")
            ctx.fail(shape, "an instance needs exactly one shapegroup");
        const DMat4 to_world = parent * object_transform(ctx, shape);
        for (pugi::xml_node inner : ctx.objects(groups[0], "shape"))
            add_shape_at(ctx, inner, to_world, material_of, depth + 1);
        return;
    }
    DMat4 local(1.0);
    Mesh mesh = object_mesh(ctx, shape, local);
    const bool face_normals = ctx.get_bool(shape, "face_normals", false);
    if (face_normals) mesh.normals.clear();
    transform_mesh(ctx, shape, mesh, parent * object_transform(ctx, shape) * local);
    if (mesh.normals.size() != mesh.positions.size()) {
        if (face_normals) {
            flat_normals(mesh);
        } else {
            mesh.normals.clear();
            smooth_normals(mesh);
        }
    }
    if (ctx.get_bool(shape, "flip_normals", false)) {
        for (Vec3& n : mesh.normals)
            n = -n;
        for (size_t t = 0; t < mesh.indices.size(); t += 3)
            std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
    }
    if (pugi::xml_attribute id = shape.attribute("id")) mesh.name = id.value();
    mesh.material = material_of(shape);
    ctx.scene().meshes.push_back(std::move(mesh));
}

}  // namespace

void add_shape(Context& ctx, pugi::xml_node shape, const DMat4& parent,
               const MaterialOf& material_of) {
    add_shape_at(ctx, shape, parent, material_of, 0);
}

}  // namespace mvpl::scene::mitsuba
