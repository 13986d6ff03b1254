#version 460
// Pass 3 (docs/design.md, "GPU passes"): adds the contribution of one batch of VPLs to every pixel's
// accumulated radiance, with the formulas of engine/light/vpl.h. One invocation per pixel; each
// pixel is read and written by its own invocation only.
//
// Generated per scene by engine/render/shader_program.cpp from shaders/render/shading_template.glsl:
// `//@insert X` lines are replaced by generated code and `//@if a|b` … `//@endif` blocks are kept
// only when the scene has one of the named VPL types, so that the program holds only the closure
// types and light types that occur.
#include "shared/gpu_vpl.h"
#include "shared/push_constants.h"
#include "shared/shadow_map.h"
//@if specular_chains
#include "shared/chain_record.h"
//@endif
//@insert closures
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, rgba32f) uniform readonly image2DArray g_buffer;
layout(set = 0, binding = 1, rgba32f) uniform image2D accumulation;
// A uniform buffer: the index is the same in every invocation, and lavapipe reads uniform
// buffers as scalar constant loads (measured faster than a storage buffer's per-lane gathers).
layout(std140, set = 0, binding = 2) uniform Vpls { GpuVpl vpls[kMaxShadingBatch]; };
// The shadow cubes, six layers each (shadow_pass.h), read texel by texel (cube_texel()) as a
// storage image: no sampler is bound where the scene has no textures.
layout(set = 0, binding = 3, rg32f) uniform readonly image2DArray shadow_cubes;
//@if directional|specular_chains
layout(set = 0, binding = 4) uniform sampler2DArray ortho_shadows;
//@endif
//@if specular_chains
// The receivers at the end of glossy pixels' specular chains (engine/render/chain_layer.h).
layout(std430, set = 0, binding = 5) readonly buffer ChainRecords { ChainRecord chains[]; };
//@endif

layout(push_constant) uniform ShadingPushBlock { ShadingPush pc; };

#include "shadow_lookup.glsl"
//@if directional
#include "ortho_lookup.glsl"
//@endif
// After the closures: their shading_constants.h defines MVPL_INLINE.
#include "vpl_contribution.glsl"

float local_visibility(uint i, GpuVpl v, Receiver r, vec3 to_receiver, float d, float res) {
    return visibility(i, to_receiver, d, r.ng, res);
}
//@if directional
float directional_vpl_visibility(uint i, GpuVpl v, Receiver r) {
    return directional_visibility(i, v, r.p, r.ng);
}
//@endif

// Interleaved sampling (shaders/shared/interleave.h): workgroup z is the pixel class c, and its
// 8×8 invocations are pixels of that class K apart, so that the loop over the class's VPLs is
// uniform in a workgroup (lavapipe runs both sides of a branch that diverges across its SIMD
// lanes: a per-pixel choice of VPLs would save nothing). Returns the invocation's pixel; the
// class's VPLs are first_vpl, first_vpl + vpl_step, …
ivec2 pixel_and_vpls(out uint first_vpl, out uint vpl_step) {
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    first_vpl = 0u;
    vpl_step = 1u;
    if (pc.interleave > 1u) {
        const uint k = pc.interleave;
        const uint c = gl_WorkGroupID.z;
        px = ivec2(gl_GlobalInvocationID.xy * k + uvec2(c % k, c / k));
        vpl_step = k * k;
        first_vpl = (c + vpl_step - pc.vpl_offset) % vpl_step;
    }
    return px;
}

// The surface the G-buffer holds at px (position p), seen from the camera; its emitted radiance
// goes to `emission`.
Receiver pixel_receiver(ivec2 px, vec3 p, out vec3 emission) {
    const vec4 ns_flags = imageLoad(g_buffer, ivec3(px, 1));
    const vec4 ng_metallic = imageLoad(g_buffer, ivec3(px, 2));
    const vec4 base_roughness = imageLoad(g_buffer, ivec3(px, 3));
    const vec4 specular = imageLoad(g_buffer, ivec3(px, 4));
    const vec4 emission_ior = imageLoad(g_buffer, ivec3(px, 5));
    const uint flags = uint(ns_flags.w);
    // reference::make_shading_point: a back face of a double-sided material shades with the
    // flipped normals; of a one-sided one with the unflipped ones (black from behind).
    const float side = (flags & 1u) == 0u && (flags & 2u) != 0u ? -1.0 : 1.0;
    emission = emission_ior.rgb;
    return Receiver(p, side * ns_flags.xyz, side * ng_metallic.xyz,
                    normalize(pc.camera_position.xyz - p),
                    Closure(flags >> 2u, base_roughness.rgb, ng_metallic.w, specular.rgb,
                            specular.w, base_roughness.w, emission_ior.w),
                    vec3(1.0), 0xffffffffu);
}

//@if specular_chains
// A glossy pixel: its chain's rough end receives the VPLs instead (light/specular_chain.h); a
// chain that ended without a receiver receives none (vpl_count 0).
void follow_chain(ChainRecord chain, inout Receiver r, inout uint vpl_count) {
    if (chain.state == kChainBlack) vpl_count = 0u;
    if (chain.state == kChainReceiver) {
        r.p = chain.position;
        r.n = chain.shading_normal;
        r.ng = chain.geometric_normal;
        r.wo = chain.wo;
        r.closure = Closure(chain.closure_type, chain.base_color, chain.metallic,
                            chain.specular_color, chain.specular, chain.roughness, chain.ior);
        r.weight = chain.throughput;
        r.max_vpl_length = chain.max_vpl_length;
    }
}
//@endif

// The radiance that VPLs first_vpl, first_vpl + vpl_step, … (below vpl_count) of the batch send
// towards r.wo.
vec3 sum_vpls(Receiver r, uint first_vpl, uint vpl_step, uint vpl_count) {
    const float shadow_res = float(imageSize(shadow_cubes).x);
    vec3 sum = vec3(0.0);
    for (uint i = first_vpl; i < vpl_count; i += vpl_step) {
        const GpuVpl v = vpls[i];
//@if specular_chains
        if (v.path_length > r.max_vpl_length) continue;
//@endif
//@if directional
        if (v.type == kVplDirectional) {
            add_directional_vpl(i, v, r, sum);
            continue;
        }
//@endif
//@if point|spot|area|surface
        add_local_vpl(i, v, r, shadow_res, sum);
//@endif
    }
    return sum;
}

// Adds the pixel's share to the accumulation. tag: 1 + the chain's state (1 without chains).
void accumulate(ivec2 px, vec3 sum, vec3 emitted, vec3 weight, uint vpl_step, float tag) {
    if (pc.interleave > 1u) {
        // The class's share, K² times, added to the interleaved image of the sub-pixel position,
        // which the filter adds once the position's batches are shaded (it is linear). A chain's
        // weight is left out: the filter applies the pixel's own, and reads the chain's state
        // from the tag rather than from the records (shared/interleave.h).
        const vec3 position_sum = imageLoad(accumulation, px).rgb;
        imageStore(accumulation, px, vec4(position_sum + float(vpl_step) * sum, tag));
    } else {
        const vec4 accumulated = imageLoad(accumulation, px);
        imageStore(accumulation, px, vec4(accumulated.rgb + emitted + weight * sum, 1.0));
    }
}

void main() {
    uint first_vpl, vpl_step;
    const ivec2 px = pixel_and_vpls(first_vpl, vpl_step);
    if (any(greaterThanEqual(uvec2(px), pc.size))) return;
    const vec4 position = imageLoad(g_buffer, ivec3(px, 0));
    if (position.w <= 0.0) return;
    vec3 emission;
    Receiver r = pixel_receiver(px, position.xyz, emission);
    uint vpl_count = pc.vpl_count;
    float tag = 1.0;
//@if specular_chains
    const ChainRecord chain = chains[uint(px.y) * pc.size.x + uint(px.x)];
    follow_chain(chain, r, vpl_count);
    tag += float(chain.state);
//@endif
    const vec3 emitted = (pc.flags & kAddEmission) != 0u ? emission : vec3(0.0);
    accumulate(px, sum_vpls(r, first_vpl, vpl_step, vpl_count), emitted, r.weight, vpl_step, tag);
}
