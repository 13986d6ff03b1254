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
// After the closures: their shading_constants.h defines MVPL_INLINE.
#include "shared/vpl_pair.h"
//@if spot
#include "shared/spot_falloff.h"
//@endif
//@if glossy
#include "shared/virtual_sphere.h"
#include "shared/lobe_clamp.h"

// light::widen_closure (engine/light/virtual_sphere.cpp): the lobe integrated over a virtual
// sphere of spread s² = spread2.
Closure widen_closure(Closure c, float spread2) {
    Closure w = c;
    w.roughness = vsl_roughness(roughness_to_alpha(c.roughness), spread2);
    return w;
}
//@endif

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, rgba32f) uniform readonly image2DArray g_buffer;
layout(set = 0, binding = 1, rgba32f) uniform image2D accumulation;
// A uniform buffer: the index is the same in every invocation, and lavapipe reads uniform
// buffers as scalar constant loads (measured faster than a storage buffer's per-lane gathers).
layout(std140, set = 0, binding = 2) uniform Vpls { GpuVpl vpls[kMaxShadingBatch]; };
// The shadow cubes, six layers each (shadow_pass.h), read texel by texel (cube_texel()) as a
// storage image: no sampler is bound where the scene has no textures.
layout(set = 0, binding = 3, r32f) uniform readonly image2DArray shadow_cubes;
//@if directional|specular_chains
layout(set = 0, binding = 4) uniform sampler2DArray ortho_shadows;
//@endif
//@if specular_chains
// The receivers at the end of glossy pixels' specular chains (engine/render/chain_layer.h).
layout(std430, set = 0, binding = 5) readonly buffer ChainRecords { ChainRecord chains[]; };
//@endif

layout(push_constant) uniform ShadingPushBlock { ShadingPush pc; };

#include "shadow_lookup.glsl"

// The point that receives the VPLs: the pixel's surface, or the rough end of its specular chain.
struct Receiver {
    vec3 p;
    vec3 n;   // shading normal, on the side the point is shaded from
    vec3 ng;  // geometric normal, on the same side
    vec3 wo;  // towards the camera, or back along the chain
    Closure closure;
    vec3 weight;          // the chain's throughput (1 without one)
    uint max_vpl_length;  // the longest VPL path the chain's end may receive
};

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

//@if directional
// light::vpl_contribution of directional VPL i (a distant light or the environment's), added to
// sum.
void add_directional_vpl(uint i, GpuVpl v, Receiver r, inout vec3 sum) {
    const vec3 to_light = -v.normal;
    const float cos_r = max(0.0, dot(r.n, to_light));
    // light::vpl_contribution: light from below the geometric surface never reaches it, though a
    // bump- or normal-mapped n may face it.
    if (cos_r <= 0.0 || !(dot(r.ng, to_light) > 0.0)) return;
    const vec3 f_r = closure_eval(r.closure, r.n, r.wo, to_light);
    if (max_component(f_r) <= 0.0) return;
    const float vis = (pc.flags & kShadows) != 0u ? directional_visibility(i, v, r.p, r.ng) : 1.0;
    sum += vpl_pair(v.power * vis, f_r, cos_r, VplFactors(1.0, vec3(1.0), vec3(1.0)), 1.0, 0.0);
}
//@endif

//@if point|spot|area|surface
// A VPL's own factors towards w, VPL → receiver (shared/vpl_pair.h); f widened by spread2.
VplFactors vpl_factors(GpuVpl v, vec3 w, float spread2, bool by_lobe) {
    VplFactors e = VplFactors(1.0, vec3(1.0), vec3(1.0));
//@if spot
    if (v.type == kVplSpot) e.emitter = spot_falloff(v.cos_inner, v.cos_outer, dot(v.normal, w));
//@endif
//@if area|surface
    if (v.type == kVplArea || v.type == kVplSurface) e.emitter = max(0.0, dot(v.normal, w));
//@endif
//@if surface
    if (v.type == kVplSurface) {
        const Closure c = Closure(v.closure_type, v.base_color, v.metallic, v.specular_color,
                                  v.specular, v.roughness, v.ior);
//@if glossy
        e.f = closure_eval(spread2 > 0.0 && c.type != 0u ? widen_closure(c, spread2) : c,
                           v.shading_normal, v.wi, w);
        if (by_lobe) e.f_diffuse = closure_eval_diffuse(c, v.shading_normal, v.wi, w);
//@endif
//@if !glossy
        e.f = closure_eval(c, v.shading_normal, v.wi, w);
//@endif
    }
//@endif
    return e;
}

// light::vpl_contribution of VPL i at a point (point, spot, area or surface), added to sum.
void add_local_vpl(uint i, GpuVpl v, Receiver r, float shadow_res, inout vec3 sum) {
    const vec3 to_receiver = r.p - v.position;
    const float d2 = dot(to_receiver, to_receiver);
    if (!(d2 > 0.0)) return;
    const float d = sqrt(d2);
    const vec3 w = to_receiver / d;  // VPL → receiver
    const float cos_r = max(0.0, dot(r.n, -w));
    // As for directional VPLs: none from below the geometric surface, whatever n says.
    if (cos_r <= 0.0 || !(dot(r.ng, -w) > 0.0)) return;
    float spread2 = 0.0;
    bool by_lobe = false;
//@if glossy
    // Area and surface VPLs are virtual spherical lights: both lobes widened (light::
    // vpl_contribution; shared/virtual_sphere.h).
    spread2 = v.type == kVplArea || v.type == kVplSurface ? vsl_spread2(pc.vsl_r2, d2) : 0.0;
    // A pair with a widened glossy lobe in it is clamped lobe by lobe (light::vpl_contribution;
    // shared::vsl_glossy_d2): f_vpl's diffuse lobe alone, an area VPL's emission counting as
    // diffuse.
    by_lobe = clamps_by_lobe(spread2, pc.d_min2,
                             r.closure.type != 0u ||
                                 (v.type == kVplSurface && v.closure_type != 0u));
//@endif
    const VplFactors e = vpl_factors(v, w, spread2, by_lobe);
    if (e.emitter <= 0.0 || max_component(e.f) <= 0.0) return;
//@if glossy
    const vec3 f_r =
        closure_eval(spread2 > 0.0 && r.closure.type != 0u ? widen_closure(r.closure, spread2)
                                                           : r.closure,
                     r.n, r.wo, -w);
//@endif
//@if !glossy
    const vec3 f_r = closure_eval(r.closure, r.n, r.wo, -w);
//@endif
    if (max_component(f_r) <= 0.0) return;
    const float vis =
        (pc.flags & kShadows) != 0u ? visibility(i, to_receiver, d, r.ng, shadow_res) : 1.0;
//@if glossy
    if (by_lobe) {
        sum += vpl_pair_by_lobe(v.power * vis, f_r, closure_eval_diffuse(r.closure, r.n, r.wo, -w),
                                cos_r, e, d2, pc.vsl_r2, pc.d_min2);
        return;
    }
//@endif
    sum += vpl_pair(v.power * vis, f_r, cos_r, e, d2, pc.d_min2);
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
