#include "engine/material/scene_materials.h"

namespace mvpl::material {

SceneMaterials::SceneMaterials(const scene::Scene& scene) : m_textures(scene.textures) {
    m_graphs.reserve(scene.materials.size());
    for (const scene::Material& m : scene.materials)
        m_graphs.push_back(graph_from_gltf(m));
}

}  // namespace mvpl::material
