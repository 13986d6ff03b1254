// The VPL record of engine/light/vpl.h as the shading pass reads it from a uniform buffer:
// std140, which lays this struct out as std430 would (prelude.h). The one definition for
// engine/render/gpu_vpl.h and shaders/render/shading_template.glsl.
#ifndef MVPL_SHADERS_SHARED_GPU_VPL_H
#define MVPL_SHADERS_SHARED_GPU_VPL_H

#include "prelude.h"

MVPL_SHARED_BEGIN

// GpuVpl::type: engine/light/vpl.h, VplType.
const uint kVplPoint = 0u;
const uint kVplSpot = 1u;
const uint kVplArea = 2u;
const uint kVplSurface = 3u;
const uint kVplDirectional = 4u;

// Directional VPLs carry their orthographic map (engine/render/directional_frame.h) in the fields
// they do not otherwise use: position = the map's origin (u, v, w), shading_normal = its u axis,
// wi = its v axis, map_extent and map_depth; normal = the unit direction of travel.
struct GpuVpl {
    vec3 position;
    uint type;
    vec3 normal;  // Area/Surface: geometric normal; Spot/Directional: direction of travel
    float cos_inner;
    vec3 shading_normal;
    float cos_outer;
    vec3 wi;
    float map_extent;
    vec3 power;
    float map_depth;
    // base_color … ior: the closure (closure.h), spelled out rather than taken from its list
    // because here they are a buffer layout, each vec3 paired with a float.
    vec3 base_color;
    float metallic;
    vec3 specular_color;
    float specular;
    float roughness;
    float ior;
    uint closure_type;  // engine/material/closure.h, ClosureType
    uint path_length;   // segments from the light (engine/light/vpl.h)
};

#ifdef __cplusplus
MVPL_STD430_MEMBER(GpuVpl, position);
MVPL_STD430_MEMBER(GpuVpl, normal);
MVPL_STD430_MEMBER(GpuVpl, shading_normal);
MVPL_STD430_MEMBER(GpuVpl, wi);
MVPL_STD430_MEMBER(GpuVpl, power);
MVPL_STD430_MEMBER(GpuVpl, base_color);
MVPL_STD430_MEMBER(GpuVpl, specular_color);
// 128: the std140 array stride, and 512 of them fill a 64 KiB uniform buffer (shading_pass.cpp).
static_assert(sizeof(GpuVpl) == 128);
#endif

// The VPL array of the shading pass is a uniform buffer (lavapipe reads it ~1.5–2× faster than a
// storage buffer): 512 × 128 bytes = 64 KiB, the maxUniformBufferRange of lavapipe and desktop
// GPUs. A device with the spec's minimum of 16 KiB would need a smaller constant here.
const uint kMaxShadingBatch = 512u;

MVPL_SHARED_END

#endif
