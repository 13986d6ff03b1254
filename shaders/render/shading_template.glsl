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
//@if glossy
#include "shared/virtual_sphere.h"

// light::widen_closure (engine/light/virtual_sphere.cpp): the lobe integrated over a virtual
// sphere of spread s² = spread2.
Closure widen_closure(Closure c, float spread2) {
    Closure w = c;
    w.roughness = sqrt(vsl_alpha(roughness_to_alpha(c.roughness), spread2));
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

// Shadow test against the VPL's distance cube, in two lookups.
//
// The receiver-plane test. Nearest sampling reads the texel that contains the direction w to the
// receiver; what that texel stores is the distance rasterised along its CENTRE direction w_c, up
// to half a texel diagonal (0.71 texel angles τ) away. Instead of a slope-scaled bias (which, at
// grazing angles, must grow to d · tan θ · τ and then reaches through walls), the receiver's own
// plane is intersected along w_c: d_c = n·(p − x)/(n·w_c) is the distance the texel would store
// if nothing stood in front of the receiver's plane, so the receiver is lit when stored ≥ d_c, up
// to kConstantBias for the rounding of interpolated distances (~1e-6 relative) and
// kFootprintBias footprints (d · τ) so that a surface meeting the receiver in a concave corner
// does not shadow it. Where w_c runs nearly parallel to the plane, d_c is unreliable and the
// receiver's own distance d with a bounded slope bias is used instead.
//
// The junction test (issue 13, thin walls). The plane test cannot see a zero-thickness wall that
// stands on the receiver's surface: within about a footprint behind the wall's foot the texel's
// centre may pass under the wall and hit the floor in front of it, which lies in the receiver's
// plane, and the footprint allowance lets the wall's foot itself pass; a thick wall hides that
// band, a single plane leaves it in view as a bright line along each junction (measured: 88
// leaking pixels per VPL set in tests/render/test_thin_walls.cpp). The second lookup moves the
// receiver off its surface towards the VPL by kNormalOffset · d · τ · sin θ (a normal offset:
// along w_c the receiver's plane then lies (kNormalOffset − 0.71) · d · τ · tan θ beyond the
// moved point, so the point's own distance can be compared without self-shadowing) and asks
// whether something stands in front of that point within kJunctionReach footprints: a wall at
// the receiver's foot (8: the plane test's leak band, its allowance plus half a texel diagonal,
// 1.71 footprints, plus this lookup's own spread of 0.71 · tan β footprints on a wall met at up
// to β = 83°; 4, for 72°, leaked beside a wall met at 69° at 256² faces in the family of
// test_thin_walls.cpp). Only such near occluders count, so that the offset, which moves the
// lookup by up to kNormalOffset texel angles, does not move the shadows of distant occluders
// (shadowing by every occluder through the offset lookup raised the GPU-vs-oracle error
// 2.6–3.6× on the Cornell box and the two-room scene; a reach of 8 instead of 4 left it
// unchanged). It is generated where a drawn material is double-sided or a mesh is open
// (ShaderFeatures::thin_walls): a plane is a zero-thickness wall whether one or both of its
// sides are shaded, and only a scene of closed solids does not pay for the second lookup.
const float kConstantBias = 2e-4;
const float kFootprintBias = 1.0;
const float kSlopeBias = 1.0;
const float kMaxSlope = 4.0;
const float kNormalOffset = 1.0;
const float kJunctionReach = 8.0;
// Texels drawn from a simplified level of detail hold their distance negated (shadow.frag): such a
// surface lies up to kLodFootprint footprints from the full one (shared/shadow_map.h). The plane
// test's kFootprintBias covers it already; the junction lookups and the orthographic maps' test
// allow it for those texels only, so that thin walls (never simplified) shadow as before.

// The distance a shadow texel holds, and the depth its level of detail may stand in front.
vec2 stored_distance(float texel_value, float footprint) {
    return vec2(abs(texel_value), texel_value < 0.0 ? kLodFootprint * footprint : 0.0);
}

// The cube texel that holds direction w, found as Vulkan's cube sampling finds it (spec, "Cube Map
// Face Selection", the projection shadow.vert renders with), nearest filtering and clamp to edge:
// face = major axis m_a of w, (s, t) = ((s_c, t_c) / |m_a| + 1) / 2, texel = floor((s, t) · res).
// The test needs the texel's centre anyway, so the texel is loaded from the cubes' 2D array
// (shadow_pass.h) rather than sampled through a samplerCubeArray, whose own face selection and
// coordinate handling on lavapipe cost more than all of this: the shading pass ran 1.13–1.4×
// faster without it (Cornell box, 512², batch 32, same-run A/Bs). s_c = S·w and t_c = T·w
// with the face's signed axes S and T; m = M·w = |m_a|.
struct CubeTexel {
    ivec3 texel;  // (column, row, face 0..5 in the order +X −X +Y −Y +Z −Z)
    vec3 centre;  // unit direction through the texel's centre
};

CubeTexel cube_texel(vec3 w, float res) {
    const vec3 a = abs(w);
    const bool x_major = a.x >= a.y && a.x >= a.z;
    const bool y_major = !x_major && a.y >= a.z;
    const bvec3 negative = lessThan(w, vec3(0.0));
    vec3 m_axis, s_axis, t_axis;
    int face;
    if (x_major) {
        m_axis = vec3(negative.x ? -1.0 : 1.0, 0.0, 0.0);
        s_axis = vec3(0.0, 0.0, negative.x ? 1.0 : -1.0);
        t_axis = vec3(0.0, -1.0, 0.0);
        face = negative.x ? 1 : 0;
    } else if (y_major) {
        m_axis = vec3(0.0, negative.y ? -1.0 : 1.0, 0.0);
        s_axis = vec3(1.0, 0.0, 0.0);
        t_axis = vec3(0.0, 0.0, negative.y ? -1.0 : 1.0);
        face = negative.y ? 3 : 2;
    } else {
        m_axis = vec3(0.0, 0.0, negative.z ? -1.0 : 1.0);
        s_axis = vec3(negative.z ? -1.0 : 1.0, 0.0, 0.0);
        t_axis = vec3(0.0, -1.0, 0.0);
        face = negative.z ? 5 : 4;
    }
    const float m = dot(m_axis, w);
    const vec2 st = vec2(dot(s_axis, w), dot(t_axis, w)) / m * 0.5 + 0.5;
    const vec2 texel = clamp(floor(st * res), vec2(0.0), vec2(res - 1.0));
    const vec2 centre = (texel + 0.5) / res * 2.0 - 1.0;
    return CubeTexel(ivec3(ivec2(texel), face),
                     normalize(m_axis + centre.x * s_axis + centre.y * t_axis));
}

// to_receiver = p − VPL, d = |to_receiver|, ng the receiver's geometric normal on the side it is
// shaded from.
float visibility(uint cube, vec3 to_receiver, float d, vec3 ng, float res) {
    const float footprint = d * pc.texel_angle;
    const vec3 w = to_receiver / d;
    const CubeTexel ct = cube_texel(w, res);
    const vec2 stored = stored_distance(
        imageLoad(shadow_cubes, ivec3(ct.texel.xy, 6 * int(cube) + ct.texel.z)).r, footprint);
    const vec3 wc = ct.centre;
    const float along = dot(ng, wc);
    const float d_plane = dot(ng, to_receiver) / along;
    const float cos_r = abs(dot(ng, w));
    bool lit;
    if (abs(along) > 0.05 * cos_r && d_plane > 0.5 * d && d_plane < 2.0 * d) {
        // kFootprintBias ≥ kLodFootprint: the allowance of simplified casters is in it.
        lit = stored.x >= d_plane - (kConstantBias * d + kFootprintBias * footprint);
    } else {
        const float tan_r = min(sqrt(max(0.0, 1.0 - cos_r * cos_r)) / max(cos_r, 1e-6), kMaxSlope);
        lit = stored.x >= d - d * (kConstantBias + kSlopeBias * pc.texel_angle * tan_r) - stored.y;
    }

//@if thin_walls
    const float cos_g = dot(ng, w);
    const vec3 towards_vpl = cos_g <= 0.0 ? ng : -ng;
    const float sin_g = sqrt(max(0.0, 1.0 - cos_g * cos_g));
    const vec3 lookup = to_receiver + towards_vpl * (kNormalOffset * footprint * sin_g);
    const float d_lookup = length(lookup);
    const CubeTexel moved = cube_texel(lookup / d_lookup, res);
    const vec2 near = stored_distance(
        imageLoad(shadow_cubes, ivec3(moved.texel.xy, 6 * int(cube) + moved.texel.z)).r,
        footprint);
    const float in_front = d_lookup - near.x;
    if (in_front > kConstantBias * d_lookup + near.y && in_front < kJunctionReach * footprint)
        lit = false;
//@endif
    return lit ? 1.0 : 0.0;
}

//@if directional
// The same test against a directional VPL's orthographic map (directional_frame.h): w is the
// receiver's distance along the direction of travel from the map's near plane, and a texel is
// extent / resolution wide (in place of d · texel_angle). The first lookup allows a slope bias;
// the junction lookup (thin walls) is visibility()'s with parallel rays, its reach grown by that
// bias, which is what lets a wall's foot pass the first.
// Every surface is drawn into the map, so a receiver whose own texel is empty lies within a texel
// of the outline of everything the map holds (a triangle covers a texel only where it covers the
// texel's centre: Vulkan spec, "Polygon Rasterization"), and what lies over it is in the texels
// beside it. It is shadowed when one of the 3 × 3 holds a surface in front of both the receiver
// and the receiver's own plane at that texel's centre (its own surface there is not in front).
// Without it light entered a closed room of one-sided walls at its edges (docs/results.md,
// "One-sided occluders"). map: the receiver in map coordinates; res: the map's side in texels.
bool occluded_at_outline(uint layer, GpuVpl v, vec3 map, vec3 ng, float texel, float res) {
    const vec3 n = vec3(dot(ng, v.shading_normal), dot(ng, v.wi), dot(ng, v.normal));
    const float n_z = abs(n.z) > 1e-6 ? n.z : 1e-6;
    const ivec2 own = ivec2(floor(map.xy / texel));
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            const ivec2 t = own + ivec2(dx, dy);
            if (any(lessThan(t, ivec2(0))) || any(greaterThanEqual(t, ivec2(int(res))))) continue;
            const vec2 stored =
                stored_distance(texelFetch(ortho_shadows, ivec3(t, int(layer)), 0).r, texel);
            const vec2 offset = (vec2(t) + 0.5) * texel - map.xy;
            const float plane = min(map.z, map.z - dot(n.xy, offset) / n_z);
            if (stored.x < plane - (kConstantBias * map.z + kFootprintBias * texel + stored.y))
                return true;
        }
    }
    return false;
}

float directional_visibility(uint layer, GpuVpl v, vec3 p, vec3 ng) {
    const vec3 map = vec3(dot(p, v.shading_normal), dot(p, v.wi), dot(p, v.normal)) - v.position;
    const float res = float(textureSize(ortho_shadows, 0).x);
    const float texel = v.map_extent / res;
    const vec2 stored = stored_distance(
        textureLod(ortho_shadows, vec3(map.xy / v.map_extent, float(layer)), 0.0).r, texel);
    const float cos_r = abs(dot(ng, v.normal));
    const float tan_r = min(sqrt(max(0.0, 1.0 - cos_r * cos_r)) / max(cos_r, 1e-6), kMaxSlope);
    const float bias = kConstantBias * map.z + kSlopeBias * texel * tan_r + stored.y;
    bool lit = stored.x >= map.z - bias;
    if (stored.x >= kShadowNoOccluder && occluded_at_outline(layer, v, map, ng, texel, res))
        lit = false;
//@if thin_walls
    const float cos_g = dot(ng, v.normal);
    const vec3 towards_light = cos_g <= 0.0 ? ng : -ng;
    const float sin_g = sqrt(max(0.0, 1.0 - cos_g * cos_g));
    const vec3 q = p + towards_light * (kNormalOffset * texel * sin_g);
    const vec3 moved = vec3(dot(q, v.shading_normal), dot(q, v.wi), dot(q, v.normal)) - v.position;
    const vec2 near = stored_distance(
        textureLod(ortho_shadows, vec3(moved.xy / v.map_extent, float(layer)), 0.0).r, texel);
    const float in_front = moved.z - near.x;
    if (in_front > kConstantBias * moved.z + near.y &&
        in_front < (kJunctionReach + kSlopeBias * tan_r) * texel)
        lit = false;
//@endif
    return lit ? 1.0 : 0.0;
}
//@endif

//@if spot
float spot_falloff(GpuVpl v, float cos_angle) {
    // light::spot_attenuation
    const float scale = 1.0 / max(1e-3, v.cos_inner - v.cos_outer);
    const float t = clamp((cos_angle - v.cos_outer) * scale, 0.0, 1.0);
    return t * t;
}
//@endif

void main() {
    // Interleaved sampling (shaders/shared/interleave.h): workgroup z is the pixel class c, and
    // its 8×8 invocations are pixels of that class K apart, so that the loop over the class's
    // VPLs is uniform in a workgroup (lavapipe runs both sides of a branch that diverges across
    // its SIMD lanes: a per-pixel choice of VPLs would save nothing).
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    uint first_vpl = 0u;
    uint vpl_step = 1u;
    if (pc.interleave > 1u) {
        const uint k = pc.interleave;
        const uint c = gl_WorkGroupID.z;
        px = ivec2(gl_GlobalInvocationID.xy * k + uvec2(c % k, c / k));
        vpl_step = k * k;
        first_vpl = (c + vpl_step - pc.vpl_offset) % vpl_step;
    }
    if (any(greaterThanEqual(uvec2(px), pc.size))) return;
    const vec4 position = imageLoad(g_buffer, ivec3(px, 0));
    if (position.w <= 0.0) return;
    const vec4 ns_flags = imageLoad(g_buffer, ivec3(px, 1));
    const vec4 ng_metallic = imageLoad(g_buffer, ivec3(px, 2));
    const vec4 base_roughness = imageLoad(g_buffer, ivec3(px, 3));
    const vec4 specular = imageLoad(g_buffer, ivec3(px, 4));
    const vec4 emission_ior = imageLoad(g_buffer, ivec3(px, 5));

    vec3 p = position.xyz;
    const uint flags = uint(ns_flags.w);
    // reference::make_shading_point: a back face of a double-sided material shades with the
    // flipped normals; of a one-sided one with the unflipped ones (black from behind).
    const float side = (flags & 1u) == 0u && (flags & 2u) != 0u ? -1.0 : 1.0;
    vec3 n = side * ns_flags.xyz;
    vec3 ng = side * ng_metallic.xyz;
    vec3 wo = normalize(pc.camera_position.xyz - p);
    Closure receiver = Closure(flags >> 2u, base_roughness.rgb, ng_metallic.w, specular.rgb,
                               specular.w, base_roughness.w, emission_ior.w);
    vec3 weight = vec3(1.0);
    uint max_vpl_length = 0xffffffffu;
    uint vpl_count = pc.vpl_count;
//@if specular_chains
    // A glossy pixel: its chain's rough end receives the VPLs instead (light/specular_chain.h).
    const ChainRecord chain = chains[uint(px.y) * pc.size.x + uint(px.x)];
    if (chain.state == kChainBlack) vpl_count = 0u;
    if (chain.state == kChainReceiver) {
        p = chain.position;
        n = chain.shading_normal;
        ng = chain.geometric_normal;
        wo = chain.wo;
        receiver = Closure(chain.closure_type, chain.base_color, chain.metallic,
                           chain.specular_color, chain.specular, chain.roughness, chain.ior);
        weight = chain.throughput;
        max_vpl_length = chain.max_vpl_length;
    }
//@endif

    const float shadow_res = float(imageSize(shadow_cubes).x);

    const vec3 emitted = (pc.flags & kAddEmission) != 0u ? emission_ior.rgb : vec3(0.0);
    vec3 sum = vec3(0.0);
    for (uint i = first_vpl; i < vpl_count; i += vpl_step) {
        const GpuVpl v = vpls[i];
//@if specular_chains
        if (v.path_length > max_vpl_length) continue;
//@endif
//@if directional
        if (v.type == kVplDirectional) {
            const vec3 to_light = -v.normal;
            const float cos_r = max(0.0, dot(n, to_light));
            // light::vpl_contribution: light from below the geometric surface never reaches it,
            // though a bump- or normal-mapped n may face it.
            if (cos_r <= 0.0 || !(dot(ng, to_light) > 0.0)) continue;
            const vec3 f_r = closure_eval(receiver, n, wo, to_light);
            if (max_component(f_r) <= 0.0) continue;
            const float vis =
                (pc.flags & kShadows) != 0u ? directional_visibility(i, v, p, ng) : 1.0;
            sum += v.power * vis * f_r * cos_r;
            continue;
        }
//@endif
//@if point|spot|area|surface
        const vec3 r = p - v.position;
        const float d2 = dot(r, r);
        if (!(d2 > 0.0)) continue;
        const float d = sqrt(d2);
        const vec3 w = r / d;  // VPL → receiver
        const float cos_r = max(0.0, dot(n, -w));
        // As for directional VPLs: none from below the geometric surface, whatever n says.
        if (cos_r <= 0.0 || !(dot(ng, -w) > 0.0)) continue;
        float emitter = 1.0;  // the VPL's own factor: spot falloff or max(0, n_j·ω)
        vec3 f_vpl = vec3(1.0);
//@if glossy
        // Area and surface VPLs are virtual spherical lights: both lobes widened (light::
        // vpl_contribution; shared/virtual_sphere.h).
        const float spread2 =
            v.type == kVplArea || v.type == kVplSurface ? vsl_spread2(pc.vsl_r2, d2) : 0.0;
        // A pair with a widened glossy lobe in it is clamped lobe by lobe (light::
        // vpl_contribution; shared::vsl_glossy_d2): f_vpl's diffuse lobe alone, an area VPL's
        // emission counting as diffuse.
        const bool by_lobe = spread2 > 0.0 && pc.d_min2 > 0.0 &&
                             (receiver.type != 0u || (v.type == kVplSurface && v.closure_type != 0u));
        vec3 f_vpl_diffuse = vec3(1.0);
//@endif
//@if spot
        if (v.type == kVplSpot) emitter = spot_falloff(v, dot(v.normal, w));
//@endif
//@if area|surface
        if (v.type == kVplArea || v.type == kVplSurface) emitter = max(0.0, dot(v.normal, w));
//@endif
//@if surface
        if (v.type == kVplSurface) {
            const Closure c = Closure(v.closure_type, v.base_color, v.metallic, v.specular_color,
                                      v.specular, v.roughness, v.ior);
//@if glossy
            f_vpl = closure_eval(spread2 > 0.0 && c.type != 0u ? widen_closure(c, spread2) : c,
                                 v.shading_normal, v.wi, w);
            if (by_lobe) f_vpl_diffuse = closure_eval_diffuse(c, v.shading_normal, v.wi, w);
//@endif
//@if !glossy
            f_vpl = closure_eval(c, v.shading_normal, v.wi, w);
//@endif
        }
//@endif
        if (emitter <= 0.0 || max_component(f_vpl) <= 0.0) continue;
//@if glossy
        const vec3 f_r = closure_eval(spread2 > 0.0 && receiver.type != 0u
                                          ? widen_closure(receiver, spread2)
                                          : receiver,
                                      n, wo, -w);
//@endif
//@if !glossy
        const vec3 f_r = closure_eval(receiver, n, wo, -w);
//@endif
        if (max_component(f_r) <= 0.0) continue;
        const float vis =
            (pc.flags & kShadows) != 0u ? visibility(i, r, d, ng, shadow_res) : 1.0;
//@if glossy
        if (by_lobe) {
            const vec3 diffuse = closure_eval_diffuse(receiver, n, wo, -w) * f_vpl_diffuse;
            const vec3 glossy = max(f_r * f_vpl - diffuse, vec3(0.0));
            sum += v.power * vis * cos_r * emitter *
                   (diffuse / max(d2, pc.d_min2) + glossy / vsl_glossy_d2(d2, pc.vsl_r2, pc.d_min2));
            continue;
        }
//@endif
        sum += v.power * vis * f_r * cos_r * f_vpl * emitter / max(d2, pc.d_min2);
//@endif
    }
    if (pc.interleave > 1u) {
        // The class's share, K² times, added to the interleaved image of the sub-pixel position,
        // which the filter adds once the position's batches are shaded (it is linear). A chain's
        // weight is left out: the filter applies the pixel's own (shared/interleave.h).
        float tag = 1.0;
//@if specular_chains
        // 1 + the chain's state, which the filter reads here rather than from the records.
        tag += float(chain.state);
//@endif
        const vec3 position_sum = imageLoad(accumulation, px).rgb;
        imageStore(accumulation, px, vec4(position_sum + float(vpl_step) * sum, tag));
    } else {
        const vec4 accumulated = imageLoad(accumulation, px);
        imageStore(accumulation, px, vec4(accumulated.rgb + emitted + weight * sum, 1.0));
    }
}
