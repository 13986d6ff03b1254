#include "engine/material/scene_materials.h"

namespace mvpl::material {

std::vector<bool> materials_with_vertex_colors(const scene::Scene& scene) {
    std::vector<bool> out(scene.materials.size(), false);
    for (const scene::Mesh& mesh : scene.meshes) {
        if (!mesh.colors.empty() && mesh.material >= 0 && size_t(mesh.material) < out.size())
            out[size_t(mesh.material)] = true;
    }
    return out;
}

SceneMaterials::SceneMaterials(const scene::Scene& scene) : m_textures(scene.textures) {
    const std::vector<bool> coloured = materials_with_vertex_colors(scene);
    m_graphs.reserve(scene.materials.size());
    for (size_t i = 0; i < scene.materials.size(); ++i)
        m_graphs.push_back(graph_from_gltf(scene.materials[i], {.vertex_colors = coloured[i]}));
}

}  // namespace mvpl::material
