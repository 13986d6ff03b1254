#include "engine/scene/scene_loader.h"

#include <algorithm>
#include <filesystem>

#include "engine/core/error.h"

namespace mvpl::scene {

Scene load_scene(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (extension == ".gltf" || extension == ".glb") return load_gltf(path);
    throw InputError(path, "unsupported scene format" +
                               (extension.empty() ? std::string(" (no file extension)")
                                                  : " '" + extension + "'") +
                               "; expected .gltf or .glb");
}

}  // namespace mvpl::scene
