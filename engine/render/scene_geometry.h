#pragma once
// The scene's triangles on the GPU, uploaded once and shared by the G-buffer and shadow passes.
//
// Indexed, each triangle's winding normal in its first (provoking) vertex (geometry_vertex.h):
// about 84 bytes of vertex and 12 of index per triangle, against 3 × 84 de-indexed.
#include <cstdint>
#include <vector>

#include "engine/gpu/buffer.h"
#include "engine/material/closure.h"
#include "engine/material/node_graph.h"
#include "engine/render/geometry_vertex.h"
#include "engine/render/shader_program.h"
#include "engine/scene/bounds.h"
#include "engine/scene/scene.h"

namespace mvpl::render {

// What the host side draws a material with (the GPU reads the rest from the material graph).
struct GeometryMaterial {
    Rgb emission{0.0f};
    bool double_sided = false;
};

// A run of indices drawn with one material: one mesh.
struct GeometryDraw {
    uint32_t first_index = 0;  // into SceneGeometry::indices(), which hold absolute vertices
    uint32_t index_count = 0;
    uint32_t material = 0;
    // An opaque mesh of kSolidMinTriangles or more that bounds a solid (closed_surface.h), and
    // its box: seen from outside the box, its back faces lie behind its front faces.
    bool solid = false;
    Vec3 lo{0.0f};
    Vec3 hi{0.0f};
};

class SceneGeometry {
public:
    // Below this, whether a mesh bounds a solid is not worth finding out (its back faces cost
    // little to draw); the shadow clusters' levels of detail start there too.
    static constexpr size_t kSolidMinTriangles = 4096;

    SceneGeometry(gpu::Context& context, const scene::Scene& scene);

    const gpu::Buffer& vertices() const { return m_vertices; }
    const gpu::Buffer& indices() const { return m_indices; }
    const std::vector<GeometryDraw>& draws() const { return m_draws; }
    const std::vector<GeometryMaterial>& materials() const { return m_materials; }
    // The scene's material graphs, in material order (what the G-buffer shader resolves).
    const std::vector<material::MaterialGraph>& graphs() const { return m_graphs; }
    // Scene::drawn_materials(): the materials the G-buffer generates code for.
    const std::vector<bool>& drawn() const { return m_drawn; }
    // The scene's decoded textures (what the graphs' image-texture nodes read).
    const std::vector<scene::Texture>& textures() const { return *m_textures; }
    // What the scene can produce (scene_features), with or without surface VPLs.
    ShaderFeatures features(bool surface_vpls) const {
        ShaderFeatures f = m_features;
        f.vpl_types[size_t(light::VplType::Surface)] = surface_vpls;
        return f;
    }
    uint32_t vertex_count() const { return m_vertex_count; }
    const scene::Bounds& bounds() const { return m_bounds; }
    // The scene's environment: what pixels that no surface covers show.
    const scene::Environment& environment() const { return m_environment; }

private:
    gpu::Buffer m_vertices;
    gpu::Buffer m_indices;
    std::vector<GeometryDraw> m_draws;
    std::vector<GeometryMaterial> m_materials;
    std::vector<material::MaterialGraph> m_graphs;
    std::vector<bool> m_drawn;
    ShaderFeatures m_features;
    // The scene's, not a copy (2048² textures hold 64 MiB of float texels each): the scene
    // outlives its geometry, as it outlives the renderer that holds both (VplRenderer::Impl).
    const std::vector<scene::Texture>* m_textures;
    uint32_t m_vertex_count = 0;
    scene::Bounds m_bounds;
    scene::Environment m_environment;
};

// Writes the generated GLSL of every stage that the renderer builds for this geometry
// (g_buffer.vert, g_buffer.frag, shading.comp) into dir; InputError when it cannot.
void dump_scene_shaders(const std::string& dir, const SceneGeometry& geometry, bool surface_vpls);

}  // namespace mvpl::render
