#pragma once
// The VPL record as the shading pass reads it from a uniform buffer: std140 (the same layout as
// std430 for this struct), mirrored by shaders/render/vpl.glsl.
#include <cstdint>
#include <span>
#include <vector>

#include "engine/light/vpl.h"
#include "engine/scene/bounds.h"

namespace mvpl::render {

// Directional VPLs carry their orthographic map (directional_frame.h) in the fields they do not
// otherwise use: position = the map's origin (u, v, w), shading_normal = its u axis, wi = its
// v axis, map_extent and map_depth; normal = the unit direction of travel.
struct GpuVpl {
    float position[3];
    uint32_t type;
    float normal[3];
    float cos_inner;
    float shading_normal[3];
    float cos_outer;
    float wi[3];
    float map_extent;
    float power[3];
    float map_depth;
    float base_color[3];
    float metallic;
    float specular_color[3];
    float specular;
    float roughness;
    float ior;
    uint32_t closure_type;  // material::ClosureType of the closure
    float pad3;
};
static_assert(sizeof(GpuVpl) == 128);

// The closure is clamped to its glTF ranges here, as the CPU Bsdf does on construction.
// bounds: the scene's, which directional VPLs' maps cover.
GpuVpl to_gpu_vpl(const light::Vpl& vpl, const scene::Bounds& bounds);
std::vector<GpuVpl> to_gpu_vpls(std::span<const light::Vpl> vpls, const scene::Bounds& bounds);

}  // namespace mvpl::render
