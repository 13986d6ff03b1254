#pragma once
// Reading a latitude-longitude environment map (environment.h for its orientation): Radiance
// `.hdr` through stb_image, `.exr` through OpenEXR. Throws InputError naming the file and what is
// wrong: missing or undecodable (the decoder's reason), not twice as wide as high, a NaN,
// negative or infinite texel (the first one's position), or too large for memory.
#include <cstdint>
#include <memory>
#include <string>

#include "engine/scene/environment.h"

namespace mvpl::scene {

// 8192 × 4096 texels and a little more (12 bytes each, 402 MiB): beyond that the map, its
// sampling tables and the GPU's copy would not fit the machines mvpl runs on.
inline constexpr int64_t kMaxEnvironmentTexels = int64_t(1) << 26;

std::shared_ptr<const EnvironmentMap> load_environment_map(const std::string& path);

}  // namespace mvpl::scene
