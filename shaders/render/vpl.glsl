// The VPL record of engine/light/vpl.h as the shading pass reads it (std140, which lays this
// struct out as std430 would; mirrored by engine/render/gpu_vpl.h, GpuVpl).
const uint kVplPoint = 0u;
const uint kVplSpot = 1u;
const uint kVplArea = 2u;
const uint kVplSurface = 3u;
const uint kVplDirectional = 4u;

// Directional: position = the orthographic map's origin (u, v, w), shading_normal and wi = its
// u and v axes, normal = the unit direction of travel (engine/render/gpu_vpl.h).
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
    vec3 base_color;
    float metallic;
    vec3 specular_color;
    float specular;
    float roughness;
    float ior;
    uint closure_type;  // engine/material/node_eval.h, ClosureType
    float pad3;
};
