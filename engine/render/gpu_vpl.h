#pragma once
// The VPL record as the shading pass reads it from a uniform buffer. Its layout is defined once,
// for C++ and GLSL, in shaders/shared/gpu_vpl.h.
#include <span>
#include <vector>

#include "engine/light/vpl.h"
#include "engine/scene/bounds.h"
#include "shaders/shared/gpu_vpl.h"

namespace mvpl::render {

using shared::GpuVpl;

// The closure is clamped to its glTF ranges here, as the CPU Bsdf does on construction.
// bounds: the scene's, which directional VPLs' maps cover.
GpuVpl to_gpu_vpl(const light::Vpl& vpl, const scene::Bounds& bounds);
std::vector<GpuVpl> to_gpu_vpls(std::span<const light::Vpl> vpls, const scene::Bounds& bounds);

}  // namespace mvpl::render
