#include "engine/render/scene_geometry.h"

#include "engine/gpu/gpu_error.h"
#include "engine/material/material_eval.h"

namespace mvpl::render {
namespace {

void store(float out[3], const Vec3& v) {
    out[0] = v.x;
    out[1] = v.y;
    out[2] = v.z;
}

}  // namespace

SceneGeometry::SceneGeometry(gpu::Context& context, const scene::Scene& scene) {
    for (const scene::Material& m : scene.materials) {
        m_materials.push_back({material::clamp_to_valid_ranges(material::factor_closure(m)),
                               m.emission(), m.double_sided});
    }
    if (m_materials.empty()) m_materials.push_back({});

    std::vector<GeometryVertex> vertices;
    vertices.reserve(scene.triangle_count() * 3);
    for (const scene::Mesh& mesh : scene.meshes) {
        GeometryDraw draw;
        draw.first_vertex = uint32_t(vertices.size());
        draw.material = mesh.material >= 0 && size_t(mesh.material) < m_materials.size()
                            ? uint32_t(mesh.material)
                            : 0u;
        for (size_t t = 0; t < mesh.triangle_count(); ++t) {
            const uint32_t* idx = &mesh.indices[3 * t];
            const Vec3& p0 = mesh.positions[idx[0]];
            const Vec3& p1 = mesh.positions[idx[1]];
            const Vec3& p2 = mesh.positions[idx[2]];
            // As trace::make_interaction: the winding normal, unit (zero for a degenerate
            // triangle, which rasterises to nothing anyway).
            const Vec3 cross = glm::cross(p1 - p0, p2 - p0);
            const float len = glm::length(cross);
            const Vec3 face = len > 0.0f ? cross / len : Vec3(0.0f);
            for (int k = 0; k < 3; ++k) {
                GeometryVertex v{};
                store(v.position, mesh.positions[idx[k]]);
                store(v.normal, mesh.normals.empty() ? face : mesh.normals[idx[k]]);
                store(v.face_normal, face);
                vertices.push_back(v);
                m_bounds.extend(mesh.positions[idx[k]]);
            }
        }
        draw.vertex_count = uint32_t(vertices.size()) - draw.first_vertex;
        if (draw.vertex_count > 0) m_draws.push_back(draw);
    }
    if (vertices.empty()) throw gpu::GpuError("scene '" + scene.path + "' has no triangles");
    m_vertex_count = uint32_t(vertices.size());
    m_vertices =
        gpu::Buffer(context, vertices.size() * sizeof(GeometryVertex), gpu::BufferUsage::vertex,
                    gpu::MemoryLocation::device, "scene vertices");
    m_vertices.upload(vertices);
}

}  // namespace mvpl::render
