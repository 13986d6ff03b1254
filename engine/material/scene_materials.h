#pragma once
// A scene's materials as node graphs (graph_from_gltf, once per material) with the scene's
// textures: what every CPU caller evaluates — the path tracer, the light tracer and the light
// sampler through trace::ShadingPoint and light::LightSampler, the CPU oracle — so that the CPU
// reads the same graphs from which the G-buffer's GLSL is generated.
#include <vector>

#include "engine/material/graph_eval.h"
#include "engine/material/node_graph.h"
#include "engine/scene/scene.h"

namespace mvpl::material {

// Per material: whether a mesh with COLOR_0 uses it.
std::vector<bool> materials_with_vertex_colors(const scene::Scene& scene);

class SceneMaterials {
public:
    // Keeps a reference to scene.textures: the scene must outlive this.
    explicit SceneMaterials(const scene::Scene& scene);

    // Material indices are those of scene::Mesh::material (the loaders check them).
    const MaterialGraph& graph(int material) const { return m_graphs[size_t(material)]; }
    const std::vector<MaterialGraph>& graphs() const { return m_graphs; }

    ClosureParams closure(int material, const SurfacePoint& p) const {
        return evaluate_closure(graph(material), m_textures, p);
    }
    Rgb emission(int material, const SurfacePoint& p) const {
        return evaluate_emission(graph(material), m_textures, p);
    }
    // p.frame.n unless the graph has a normal node.
    Vec3 normal(int material, const SurfacePoint& p) const {
        return evaluate_normal(graph(material), m_textures, p);
    }
    bool has_normal_node(int material) const { return graph(material).normal >= 0; }
    // The graph has an emission node: the material's triangles are area lights.
    bool is_emissive(int material) const { return graph(material).emission >= 0; }
    bool double_sided(int material) const { return graph(material).double_sided; }
    // KHR_materials_transmission with KHR_materials_volume: the surface bounds a solid, so its
    // frame keeps facing out whichever side a ray hits (trace::make_shading_point).
    bool solid(int material) const {
        const MaterialGraph& g = graph(material);
        return g.transmission.node >= 0 && !g.thin_walled;
    }
    // glTF alphaMode MASK: whether the material cuts its surface at p (alpha < alphaCutoff);
    // BLEND as hashed transparency: whether a hit with the uniform number u ∈ [0, 1) (a hash of
    // the ray, so that a hit is deterministic) passes through it (u ≥ alpha).
    bool masked(int material) const { return graph(material).masked(); }
    bool alpha_tested(int material) const { return graph(material).alpha_tested(); }
    bool cut(int material, const SurfacePoint& p, float u = 0.0f) const {
        const MaterialGraph& g = graph(material);
        if (!g.alpha_tested()) return false;
        const float alpha = evaluate_input(g, g.alpha, m_textures, p).x;
        return g.masked() ? alpha < g.alpha_cutoff : u >= alpha;
    }

private:
    const std::vector<scene::Texture>& m_textures;
    std::vector<MaterialGraph> m_graphs;
};

}  // namespace mvpl::material
