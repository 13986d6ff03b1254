// The push constants of the render passes, one definition for the C++ that pushes them and the
// GLSL that reads them (prelude.h). A stage declares its block around one of these structs,
//     layout(push_constant) uniform ShadowPushBlock { ShadowPush pc; };
// which lays it out as the members would be laid out in the block itself (std430).
#ifndef MVPL_SHADERS_SHARED_PUSH_CONSTANTS_H
#define MVPL_SHADERS_SHARED_PUSH_CONSTANTS_H

#include "prelude.h"

MVPL_SHARED_BEGIN

// The G-buffer pass (engine/render/g_buffer_pass.cpp; shaders/render/g_buffer_push.glsl): the
// camera and which material the draw uses.
struct GBufferPush {
    mat4 view_proj;  // reversed infinite perspective, Vulkan clip space (image row 0 at the top)
    uint material_flags;  // bit 0: double-sided
    uint material;        // index of the scene material: resolve_material's argument
    uint seed;            // of glTF BLEND's hashed transparency: one per sub-pixel position
};

// The material pass of the G-buffer (g_buffer_pass.cpp; shaders/render/material_template.glsl).
struct MaterialPush {
    uvec2 size;
};

// The sum of the emitted radiance seen directly over a progressive render's G-buffers
// (engine/render/emission_sum.cpp; shaders/render/emission_sum.comp).
struct EmissionPush {
    uvec2 size;
    uint layer;  // kGBufferEmission
    uint flags;  // kEmission* below
};
const uint kEmissionBackground = 1u;  // uncovered pixels take the background image
const uint kEmissionChains = 2u;      // add the chain records' emitted radiance (chain_record.h)

// A shadow cube face (engine/render/shadow_pass.cpp; shaders/render/shadow.vert).
struct ShadowPush {
    vec4 vpl_near;  // xyz: the VPL's position; w: the near distance (geometry closer is ignored)
    uvec4 face;     // x: cube face, +X −X +Y −Y +Z −Z; y: the material, z: the seed of glTF
                    // BLEND's hash (alpha-tested pipeline, shadow_masked.frag); w: 1 for the
                    // casters of a simplified level of detail
};

// The orthographic map of a directional VPL (shadow_pass.cpp; shaders/render/shadow_ortho.vert).
struct OrthoPush {
    vec4 u_origin;    // xyz: map x axis, w: its origin
    vec4 v_origin;    // map y axis and origin
    vec4 dir_origin;  // direction of travel and the near plane's w
    vec4 extents;     // x: window side, y: depth range; z: the material, w: the seed of glTF
                      // BLEND's hash, as floats (alpha-tested pipeline, shadow_masked.frag);
                      // other pipelines' z: 1 for the casters of a simplified level of detail
};

// A batch of the shading pass (engine/render/shading_pass.cpp;
// shaders/render/shading_template.glsl).
struct ShadingPush {
    vec4 camera_position;  // xyz
    float d_min2;          // squared clamping distance of the geometric term
    float texel_angle;     // angle of a shadow texel at the centre of a face: 2 / resolution
    uint vpl_count;
    uint flags;  // kAddEmission | kShadows
    uvec2 size;
    // Interleaved sampling (shaders/shared/interleave.h): K, 1 for none; with K > 1 the pixel
    // of class c shades the batch's VPLs i with (vpl_offset + i) mod K² = c, times K², and
    // stores the sum instead of adding it (the filter adds it to the accumulation).
    uint interleave;
    uint vpl_offset;  // the batch's first VPL index since begin(), mod K²
    // r², the squared radius of the virtual spherical lights that area and surface VPLs become
    // (shaders/shared/virtual_sphere.h); 0: point VPLs.
    float vsl_r2;
    uint pad0;
    uint pad1;
    uint pad2;
};

// The geometry-aware filter of interleaved sampling (engine/render/interleave_filter.cpp;
// shaders/render/interleave_filter.comp).
struct InterleavePush {
    uvec2 size;
    uint interleave;  // K
    uint chains;      // 1: binding 3 holds the chain records (shared/chain_record.h); 0: unread
};
// The reduced matrix of row-column sampling (engine/render/matrix_pass.cpp;
// shaders/render/matrix_template.glsl): one dispatch adds a batch of rows' entries to every
// column's squared norm and count sketch.
struct MatrixPush {
    float d_min2;       // as ShadingPush's
    float vsl_r2;       // as ShadingPush's
    float texel_angle;  // of the rows' cubes: 2 / resolution
    uint flags;         // kShadows
    uint column_count;  // VPLs in the pool
    uint row_count;     // rows (and their cubes) in the batch, at most kMaxMatrixRows
    uint dims;          // of the sketch, at most kMaxSketchDims
};
const uint kMaxSketchDims = 64u;
// Rows of a matrix batch: 512 × 128-byte records fill a 64 KiB uniform buffer, as GpuVpl's do.
const uint kMaxMatrixRows = 512u;

const uint kAddEmission = 1u;  // ShadingPush::flags: add the G-buffer's emitted radiance
const uint kShadows = 2u;      // ShadingPush::flags, MatrixPush::flags: test visibility

#ifdef __cplusplus
MVPL_STD430_MEMBER(GBufferPush, view_proj);
static_assert(sizeof(GBufferPush) == 76);
MVPL_STD430_MEMBER(MaterialPush, size);
MVPL_STD430_MEMBER(EmissionPush, size);
static_assert(sizeof(EmissionPush) == 16);
MVPL_STD430_MEMBER(ShadowPush, vpl_near);
MVPL_STD430_MEMBER(ShadowPush, face);
static_assert(sizeof(ShadowPush) == 32);
MVPL_STD430_MEMBER(OrthoPush, u_origin);
MVPL_STD430_MEMBER(OrthoPush, v_origin);
MVPL_STD430_MEMBER(OrthoPush, dir_origin);
MVPL_STD430_MEMBER(OrthoPush, extents);
static_assert(sizeof(OrthoPush) == 64);
MVPL_STD430_MEMBER(ShadingPush, camera_position);
MVPL_STD430_MEMBER(ShadingPush, size);
MVPL_STD430_MEMBER(ShadingPush, interleave);
MVPL_STD430_MEMBER(ShadingPush, vsl_r2);
static_assert(sizeof(ShadingPush) == 64);
MVPL_STD430_MEMBER(InterleavePush, size);
static_assert(sizeof(InterleavePush) == 16);
MVPL_STD430_MEMBER(MatrixPush, dims);
static_assert(sizeof(MatrixPush) == 28);
#endif

MVPL_SHARED_END

#endif
