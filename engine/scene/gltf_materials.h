#pragma once
// glTF materials (metallic-roughness core plus the KHR extensions the renderer implements) as
// Scene materials.
#include <string>

#include "engine/scene/gltf_document.h"
#include "engine/scene/gltf_textures.h"
#include "engine/scene/scene.h"

namespace mvpl::scene::gltf {

// Converts every material of the file up front, so that a broken one is reported even when no
// primitive uses it; Scene::materials[i] is glTF material i. The glTF default material is appended
// the first time a primitive without a material asks for it.
class MaterialTable {
public:
    MaterialTable(const Document& doc, Scene& scene, TextureCache& textures);

    // Scene material index for a primitive's `material` property (-1: none); `usage` names the
    // primitive in messages.
    int material_for(int gltf_index, const std::string& usage);

private:
    const Document& m_doc;
    Scene& m_scene;
    int m_default = -1;
};

}  // namespace mvpl::scene::gltf
