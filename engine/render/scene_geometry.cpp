#include "engine/render/scene_geometry.h"

#include "engine/gpu/gpu_error.h"
#include "engine/material/scene_materials.h"
#include "engine/render/closed_surface.h"
#include "engine/render/host_vec3.h"

namespace mvpl::render {

namespace {

// Triangle t of `mesh` as three unshared vertices appended to `corners`; `bounds` grows by them.
void append_corners(const scene::Mesh& mesh, size_t t, std::vector<GeometryVertex>& corners,
                    scene::Bounds& bounds) {
    const uint32_t* idx = &mesh.indices[3 * t];
    const Vec3& p0 = mesh.positions[idx[0]];
    const Vec3& p1 = mesh.positions[idx[1]];
    const Vec3& p2 = mesh.positions[idx[2]];
    // As trace::make_interaction: the winding normal, unit (zero for a degenerate
    // triangle, which rasterises to nothing anyway).
    const Vec3 cross = glm::cross(p1 - p0, p2 - p0);
    const float len = glm::length(cross);
    const Vec3 face = len > 0.0f ? cross / len : Vec3(0.0f);
    // ∂p/∂u of the uv parametrisation (pbrt-v3 §3.6.2), as trace::make_interaction.
    Vec3 dpdu(0.0f);
    float sign = 1.0f;
    if (!mesh.tangents.empty()) {
        sign = mesh.tangents[idx[0]].w < 0.0f ? -1.0f : 1.0f;
    } else if (!mesh.uv0.empty()) {
        const Vec2 duv02 = mesh.uv0[idx[0]] - mesh.uv0[idx[2]];
        const Vec2 duv12 = mesh.uv0[idx[1]] - mesh.uv0[idx[2]];
        const float det = duv02.x * duv12.y - duv02.y * duv12.x;
        if (std::abs(det) > 1e-12f) dpdu = ((p0 - p2) * duv12.y - (p1 - p2) * duv02.y) / det;
    }
    for (int k = 0; k < 3; ++k) {
        GeometryVertex v{};
        store(v.position, mesh.positions[idx[k]]);
        store(v.normal, mesh.normals.empty() ? face : mesh.normals[idx[k]]);
        store(v.face_normal, face);
        const Vec2 uv0 = mesh.uv0.empty() ? Vec2(0.0f) : mesh.uv0[idx[k]];
        const Vec2 uv1 = mesh.uv1.empty() ? Vec2(0.0f) : mesh.uv1[idx[k]];
        v.uv[0] = uv0.x;
        v.uv[1] = uv0.y;
        v.uv[2] = uv1.x;
        v.uv[3] = uv1.y;
        store(v.tangent, mesh.tangents.empty() ? dpdu : Vec3(mesh.tangents[idx[k]]));
        v.tangent[3] = sign;
        const Vec4 color = mesh.colors.empty() ? Vec4(1.0f) : mesh.colors[idx[k]];
        for (int c = 0; c < 4; ++c)
            v.color[c] = color[c];
        corners.push_back(v);
        bounds.extend(mesh.positions[idx[k]]);
    }
}

// draw.solid and its bounds where the mesh bounds a solid that culling may use.
void mark_solid(const scene::Scene& scene, const scene::Mesh& mesh, GeometryDraw& draw) {
    // Masked and blended materials show their back faces through their holes.
    const bool opaque =
        mesh.material < 0 || size_t(mesh.material) >= scene.materials.size() ||
        scene.materials[size_t(mesh.material)].alpha_mode == scene::AlphaMode::Opaque;
    if (opaque && mesh.triangle_count() >= SceneGeometry::kSolidMinTriangles &&
        bounds_solid(mesh)) {
        draw.solid = true;
        draw.lo = Vec3(INFINITY);
        draw.hi = Vec3(-INFINITY);
        for (const uint32_t i : mesh.indices) {
            draw.lo = glm::min(draw.lo, mesh.positions[i]);
            draw.hi = glm::max(draw.hi, mesh.positions[i]);
        }
    }
}

}  // namespace

SceneGeometry::SceneGeometry(gpu::Context& context, const scene::Scene& scene)
    : m_graphs(material::SceneMaterials(scene).graphs()),
      m_drawn(scene.drawn_materials()),
      m_features(scene_features(scene, ShaderOptions{})),
      m_textures(&scene.textures),
      m_environment(scene.environment) {
    for (const scene::Material& m : scene.materials)
        m_materials.push_back({m.emission(), m.double_sided});
    if (m_materials.empty()) {
        m_materials.push_back({});
        // The default ClosureParams, for a scene without materials.
        scene::Material fallback;
        const material::ClosureParams c;
        fallback.base_color = c.base_color;
        fallback.metallic = c.metallic;
        fallback.roughness = c.roughness;
        m_graphs.push_back(material::graph_from_gltf(fallback));
    }

    std::vector<GeometryVertex> vertices;
    std::vector<uint32_t> indices;
    std::vector<GeometryVertex> corners;
    for (const scene::Mesh& mesh : scene.meshes) {
        GeometryDraw draw;
        draw.first_index = uint32_t(indices.size());
        corners.clear();
        corners.reserve(mesh.triangle_count() * 3);
        draw.material = mesh.material >= 0 && size_t(mesh.material) < m_materials.size()
                            ? uint32_t(mesh.material)
                            : 0u;
        for (size_t t = 0; t < mesh.triangle_count(); ++t)
            append_corners(mesh, t, corners, m_bounds);
        IndexedTriangles mesh_triangles = index_triangles(corners);
        const uint32_t base = uint32_t(vertices.size());
        vertices.insert(vertices.end(), mesh_triangles.vertices.begin(),
                        mesh_triangles.vertices.end());
        for (const uint32_t i : mesh_triangles.indices)
            indices.push_back(base + i);
        draw.index_count = uint32_t(indices.size()) - draw.first_index;
        mark_solid(scene, mesh, draw);
        if (draw.index_count > 0) m_draws.push_back(draw);
    }
    if (vertices.empty()) throw gpu::GpuError("scene '" + scene.path + "' has no triangles");
    m_vertex_count = uint32_t(vertices.size());
    m_vertices =
        gpu::Buffer(context, vertices.size() * sizeof(GeometryVertex), gpu::BufferUsage::vertex,
                    gpu::MemoryLocation::device, "scene vertices");
    m_vertices.upload(vertices);
    m_indices = gpu::Buffer(context, indices.size() * sizeof(uint32_t), gpu::BufferUsage::index,
                            gpu::MemoryLocation::device, "scene indices");
    m_indices.upload(indices);
}

void dump_scene_shaders(const std::string& dir, const SceneGeometry& geometry, bool surface_vpls) {
    // The same generators as GBufferPass and ShadingPass use when given no sources.
    const GBufferSources g =
        generate_g_buffer_sources(geometry.graphs(), geometry.textures(), geometry.drawn());
    const StageSource shading = generate_shading_source(geometry.features(surface_vpls));
    std::vector<const StageSource*> stages{&g.vert, &g.frag, &shading};
    if (g.has_material_pass()) stages.push_back(&g.material);
    const ShadowAlphaSources alpha =
        generate_shadow_alpha_sources(geometry.graphs(), geometry.textures(), geometry.drawn());
    if (!alpha.frag.name.empty()) stages.push_back(&alpha.frag);
    dump_shaders(dir, stages);
}

}  // namespace mvpl::render
