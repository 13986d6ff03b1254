#pragma once
// What a node carries besides meshes: KHR_lights_punctual lights and cameras.
#include <optional>
#include <string>

#include "engine/core/math.h"
#include "engine/scene/gltf_document.h"
#include "engine/scene/scene.h"

namespace mvpl::scene::gltf {

// The light node `node` carries (KHR_lights_punctual), placed by its world transform; nullopt
// when it has none. `where` (optional) receives its JSON path, for later messages.
std::optional<Light> node_light(const Document& doc, int node, const DMat4& world,
                                std::string* where = nullptr);

// The perspective camera node `node` carries, with the scale removed from its transform; nullopt
// when it has none or an orthographic one (not supported, skipped).
std::optional<Camera> node_camera(const Document& doc, int node, const DMat4& world);

}  // namespace mvpl::scene::gltf
