#version 460
// The reduced matrix of row-column sampling (Hašan, Pellacini, Bala 2007; engine/render/
// matrix_pass.h): entry (r, j) is VPL j's contribution to row r, the shading pass's own
// vpl_contribution.glsl times the row's chain throughput, with visibility from the row's distance
// cube instead of the VPL's (one cube per row, not per VPL: the cost of the rows' maps does not
// grow with the pool). One invocation per column; a dispatch adds a batch of rows' entries to its
// column's squared norm and count sketch (engine/manylights/reduced_matrix.h), so that the 3R
// entries of a column are never stored.
//
// Generated per scene by engine/render/shader_program.cpp, as the shading pass is: `//@insert
// closures` and `//@if` blocks keep only the scene's closure and VPL types.
#include "shared/gpu_vpl.h"
#include "shared/push_constants.h"
#include "shared/shadow_map.h"
#include "shared/chain_record.h"
//@insert closures

layout(local_size_x = 64) in;

// The batch's rows as receivers (a chain's rough end where the row continues a chain). A uniform
// buffer, as the shading pass's VPLs: every invocation reads the same row, and lavapipe reads
// uniform buffers as scalar loads (a storage buffer here made the matrix about 2× slower).
layout(std140, set = 0, binding = 0) uniform Rows { ChainRecord rows[kMaxMatrixRows]; };
layout(std430, set = 0, binding = 1) readonly buffer Vpls { GpuVpl vpls[]; };
// The batch's row cubes, six layers each (shadow_pass.h), read as the shading pass reads its own.
layout(set = 0, binding = 2, rg32f) uniform readonly image2DArray shadow_cubes;
// The count sketch's hash of the batch's row b's three entries (entries 3r … 3r + 2 of the pool's
// row r) in hash[b].xyz: bucket in the low bits, bit 31 the sign (set: subtract), as
// manylights::sketch_hash draws it.
layout(std140, set = 0, binding = 3) uniform Hash { uvec4 hash[kMaxMatrixRows]; };
// Per column: its squared norm, then its dims sketch entries.
layout(std430, set = 0, binding = 4) buffer Columns { float columns[]; };

layout(push_constant) uniform MatrixPushBlock { MatrixPush pc; };

#include "shadow_lookup.glsl"
// After the closures: their shading_constants.h defines MVPL_INLINE.
#include "vpl_contribution.glsl"

// The VPL is the receiver of row i's cube, which sees it along −to_receiver: a surface or area
// VPL with its geometric normal (on its lit side, towards the row: it emits along w only where
// n·w > 0), a point or spot VPL as a point facing the row.
float local_visibility(uint i, GpuVpl v, Receiver r, vec3 to_receiver, float d, float res) {
    const bool surface = v.type == kVplArea || v.type == kVplSurface;
    return visibility(i, -to_receiver, d, surface ? v.normal : to_receiver / d, res);
}
//@if directional
// Nothing in the row's cube along the direction the light comes from: the ray leaves the scene.
float directional_vpl_visibility(uint i, GpuVpl v, Receiver r) {
    const CubeTexel ct = cube_texel(-v.normal, float(imageSize(shadow_cubes).x));
    const float stored = imageLoad(shadow_cubes, ivec3(ct.texel.xy, 6 * int(i) + ct.texel.z)).r;
    return abs(stored) >= kShadowNoOccluder ? 1.0 : 0.0;
}
//@endif

Receiver row_receiver(ChainRecord c) {
    return Receiver(c.position, c.shading_normal, c.geometric_normal, c.wo,
                    Closure(c.closure_type, c.base_color, c.metallic, c.specular_color,
                            c.specular, c.roughness, c.ior),
                    c.throughput, c.max_vpl_length);
}

void main() {
    const uint j = gl_GlobalInvocationID.x;
    if (j >= pc.column_count) return;
    const GpuVpl v = vpls[j];
    const float res = float(imageSize(shadow_cubes).x);
    const uint stride = 1u + pc.dims;
    float norm2 = 0.0;
    float sketch[kMaxSketchDims];
    for (uint k = 0u; k < pc.dims; ++k) sketch[k] = 0.0;
    // The loop is uniform across the workgroup: every invocation reads the same row.
    for (uint b = 0u; b < pc.row_count; ++b) {
        const Receiver r = row_receiver(rows[b]);
        vec3 c = vec3(0.0);
        if (v.path_length <= r.max_vpl_length) {
//@if directional
            if (v.type == kVplDirectional) add_directional_vpl(b, v, r, c);
//@endif
//@if point|spot|area|surface
            if (v.type != kVplDirectional) add_local_vpl(b, v, r, res, c);
//@endif
            c *= r.weight;
        }
        norm2 += dot(c, c);
        for (uint ch = 0u; ch < 3u; ++ch) {
            const uint h = hash[b][ch];
            const float e = (h & 0x80000000u) != 0u ? -c[ch] : c[ch];
            sketch[h & 0x7fffffffu] += e;
        }
    }
    const uint base = j * stride;
    columns[base] += norm2;
    for (uint k = 0u; k < pc.dims; ++k) columns[base + 1u + k] += sketch[k];
}
