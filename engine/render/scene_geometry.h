#pragma once
// The scene's triangles on the GPU, uploaded once and shared by the G-buffer and shadow passes.
//
// The vertex buffer is de-indexed (three vertices per triangle): the G-buffer needs each
// triangle's winding normal, and a per-triangle attribute needs either de-indexing or
// gl_PrimitiveID in the fragment shader (which needs the geometry-shader feature). Memory is
// 84 bytes × 3 per triangle, 25 MB for 100k triangles.
#include <cstdint>
#include <vector>

#include "engine/gpu/buffer.h"
#include "engine/material/closure.h"
#include "engine/material/node_graph.h"
#include "engine/render/shader_program.h"
#include "engine/scene/bounds.h"
#include "engine/scene/scene.h"

namespace mvpl::render {

// One vertex as the passes read it (locations 0 to 5).
struct GeometryVertex {
    float position[3];
    float normal[3];       // interpolated vertex normal (the shading normal)
    float face_normal[3];  // the triangle's winding normal, the same at its three vertices
    float uv[4];           // TEXCOORD_0, TEXCOORD_1 (0 where the mesh has none)
    // As trace::make_interaction: TANGENT.xyz, else the triangle's ∂p/∂u from TEXCOORD_0, else
    // 0 (the fragment shader orthonormalises it); w = the tangent sign of the first vertex.
    float tangent[4];
    float color[4];  // COLOR_0 (linear RGBA), white where the mesh has none
};
static_assert(sizeof(GeometryVertex) == 84);

// What the host side draws a material with (the GPU reads the rest from the material graph).
struct GeometryMaterial {
    Rgb emission{0.0f};
    bool double_sided = false;
};

// A run of vertices drawn with one material: one mesh.
struct GeometryDraw {
    uint32_t first_vertex = 0;
    uint32_t vertex_count = 0;
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
    const std::vector<GeometryDraw>& draws() const { return m_draws; }
    const std::vector<GeometryMaterial>& materials() const { return m_materials; }
    // The scene's material graphs, in material order (what the G-buffer shader resolves).
    const std::vector<material::MaterialGraph>& graphs() const { return m_graphs; }
    // Scene::drawn_materials(): the materials the G-buffer generates code for.
    const std::vector<bool>& drawn() const { return m_drawn; }
    // The scene's decoded textures (what the graphs' image-texture nodes read).
    const std::vector<scene::Texture>& textures() const { return m_textures; }
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
    std::vector<GeometryDraw> m_draws;
    std::vector<GeometryMaterial> m_materials;
    std::vector<material::MaterialGraph> m_graphs;
    std::vector<bool> m_drawn;
    ShaderFeatures m_features;
    std::vector<scene::Texture> m_textures;
    uint32_t m_vertex_count = 0;
    scene::Bounds m_bounds;
    scene::Environment m_environment;
};

// Writes the generated GLSL of every stage that the renderer builds for this geometry
// (g_buffer.vert, g_buffer.frag, shading.comp) into dir; InputError when it cannot.
void dump_scene_shaders(const std::string& dir, const SceneGeometry& geometry, bool surface_vpls);

}  // namespace mvpl::render
