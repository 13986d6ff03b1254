#pragma once
#include <algorithm>
#include <filesystem>
#include <string>

namespace mvpl {

// The extension of `path` with its dot, lower-cased ("a/b.PNG" → ".png"; "" when it has none):
// what picks a scene loader or an image format, so that "X.GLTF" loads as "x.gltf" does.
inline std::string lower_extension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

}  // namespace mvpl
