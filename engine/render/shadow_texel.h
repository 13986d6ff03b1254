#pragma once
// A shadow texel on the host: the format of the shadow pass's cubes and orthographic maps, of
// their kept copies and of the shading pass's stand-ins. Two channels
// (shaders/shared/shadow_map.h): the distance, and the plane of the surface drawn there.
#include <cstdint>

#include "engine/gpu/format.h"

namespace mvpl::render {

inline constexpr gpu::Format kShadowTexelFormat = gpu::Format::rg32_float;
inline constexpr uint64_t kShadowTexelBytes = 2 * sizeof(float);

}  // namespace mvpl::render
