#pragma once
// The scene's triangles on the GPU, uploaded once and shared by the G-buffer and shadow passes.
//
// The vertex buffer is de-indexed (three vertices per triangle): the G-buffer needs each
// triangle's winding normal, and a per-triangle attribute needs either de-indexing or
// gl_PrimitiveID in the fragment shader (which needs the geometry-shader feature). Memory is
// 36 bytes × 3 per triangle, 11 MB for 100k triangles.
#include <cstdint>
#include <vector>

#include "engine/gpu/buffer.h"
#include "engine/material/closure.h"
#include "engine/scene/bounds.h"
#include "engine/scene/scene.h"

namespace mvpl::render {

// One vertex as the passes read it (locations 0, 1, 2).
struct GeometryVertex {
    float position[3];
    float normal[3];       // interpolated vertex normal (the shading normal)
    float face_normal[3];  // the triangle's winding normal, the same at its three vertices
};
static_assert(sizeof(GeometryVertex) == 36);

// What the G-buffer stores of a material (textures are not applied yet: factors only).
struct GeometryMaterial {
    material::ClosureParams closure;  // clamped to the glTF ranges, as Bsdf does
    Rgb emission{0.0f};
    bool double_sided = false;
};

// A run of vertices drawn with one material.
struct GeometryDraw {
    uint32_t first_vertex = 0;
    uint32_t vertex_count = 0;
    uint32_t material = 0;
};

class SceneGeometry {
public:
    SceneGeometry(gpu::Context& context, const scene::Scene& scene);

    const gpu::Buffer& vertices() const { return m_vertices; }
    const std::vector<GeometryDraw>& draws() const { return m_draws; }
    const std::vector<GeometryMaterial>& materials() const { return m_materials; }
    uint32_t vertex_count() const { return m_vertex_count; }
    const scene::Bounds& bounds() const { return m_bounds; }

private:
    gpu::Buffer m_vertices;
    std::vector<GeometryDraw> m_draws;
    std::vector<GeometryMaterial> m_materials;
    uint32_t m_vertex_count = 0;
    scene::Bounds m_bounds;
};

}  // namespace mvpl::render
