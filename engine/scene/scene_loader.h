#pragma once
#include <string>

#include "engine/scene/scene.h"

namespace mvpl::scene {

// Loads a scene by its file extension (.gltf, .glb). Throws InputError naming the file and what is
// wrong; never crashes or allocates without bound on malformed input.
Scene load_scene(const std::string& path);

// glTF 2.0 (.gltf with external or embedded buffers, .glb) via tinygltf.
Scene load_gltf(const std::string& path);

}  // namespace mvpl::scene
