#version 460
#extension GL_GOOGLE_include_directive : require
// Imperfect shadow maps, hole filling (Ritschel et al. 2008, section 3.3, after Marroquim et al.
// 2007's pull-push; engine/render/ism_pass.h): one workgroup per cube face of a VPL loads the
// splatted distances into shared memory, pulls them into a pyramid (each coarser texel the mean
// of its valid children that lie within kPullTolerance of their nearest, so that a coarse texel
// stands for the front surface, not a blend of an occluder and what is behind it), pushes the
// coarser values back into the texels no point reached, up to fill_levels levels (holes up to
// 2^fill_levels texels across: a face that looks into empty space stays empty), and stores the
// face into the shadow cubes as the rasterised pass would. It also clears the splat buffer for
// the next batch.
layout(local_size_x = 256) in;
#include "shared/ism.h"
#include "shared/shadow_map.h"
layout(std430, set = 0, binding = 0) buffer Depths { uint depths[]; };
layout(std430, set = 0, binding = 1) readonly buffer Vpls { IsmVpl vpls[]; };
layout(set = 0, binding = 2, r32f) uniform writeonly image2DArray shadow_cubes;
layout(push_constant) uniform IsmPushBlock { IsmPush pc; };

const float kPullTolerance = 0.05;

// The levels of a kMaxIsmResolution face, finest first: 64², 32², … 1².
shared float s_depth[4096 + 1024 + 256 + 64 + 16 + 4 + 1];

uint level_offset(uint level, uint res) {
    uint offset = 0u;
    for (uint l = 0u; l < level; ++l)
        offset += (res >> l) * (res >> l);
    return offset;
}

void main() {
    const uint face = gl_WorkGroupID.x;
    const uint v = gl_WorkGroupID.y;
    if (v >= pc.vpls) return;  // uniform per workgroup
    const uint res = pc.resolution;
    const uint slot = vpls[v].slot.x;
    const uint base = (6u * slot + face) * res * res;
    const uint lid = gl_LocalInvocationID.x;
    const uint cleared = floatBitsToUint(kShadowNoOccluder);
    for (uint i = lid; i < res * res; i += 256u) {
        s_depth[i] = uintBitsToFloat(depths[base + i]);
        depths[base + i] = cleared;
    }
    barrier();
    uint levels = 0u;
    while (levels < pc.fill_levels && (res >> (levels + 1u)) > 0u)
        ++levels;
    // Pull.
    for (uint l = 1u; l <= levels; ++l) {
        const uint side = res >> l;
        const uint fine = level_offset(l - 1u, res);
        const uint coarse = level_offset(l, res);
        for (uint i = lid; i < side * side; i += 256u) {
            const uint x = 2u * (i % side);
            const uint y = 2u * (i / side);
            const uint row = 2u * side;
            const vec4 c = vec4(s_depth[fine + y * row + x], s_depth[fine + y * row + x + 1u],
                                s_depth[fine + (y + 1u) * row + x],
                                s_depth[fine + (y + 1u) * row + x + 1u]);
            const float nearest = min(min(c.x, c.y), min(c.z, c.w));
            float sum = 0.0;
            float count = 0.0;
            for (int k = 0; k < 4; ++k) {
                if (c[k] < kShadowNoOccluder && c[k] <= nearest * (1.0 + kPullTolerance)) {
                    sum += c[k];
                    count += 1.0;
                }
            }
            s_depth[coarse + i] = count > 0.0 ? sum / count : kShadowNoOccluder;
        }
        barrier();
    }
    // Push: coarse to fine, holes only.
    for (uint l = levels; l >= 1u; --l) {
        const uint side = res >> (l - 1u);
        const uint fine = level_offset(l - 1u, res);
        const uint coarse = level_offset(l, res);
        for (uint i = lid; i < side * side; i += 256u) {
            if (s_depth[fine + i] < kShadowNoOccluder) continue;
            const uint x = (i % side) / 2u;
            const uint y = (i / side) / 2u;
            s_depth[fine + i] = s_depth[coarse + y * (side / 2u) + x];
        }
        barrier();
    }
    for (uint i = lid; i < res * res; i += 256u)
        imageStore(shadow_cubes, ivec3(int(i % res), int(i / res), int(6u * slot + face)),
                   vec4(s_depth[i], 0.0, 0.0, 0.0));
}
