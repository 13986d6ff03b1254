#version 460
#extension GL_GOOGLE_include_directive : require
// The geometry-aware filter of interleaved sampling (shaders/shared/interleave.h): adds to each
// covered pixel's accumulation the weighted mean of the interleaved batch sums (each K² times its
// class's share of the batch) over the neighbours on the same surface — with specular chains,
// over the neighbours whose receivers (the G-buffer's or the chain's rough end) are compatible,
// the pixel's own chain throughput applied to the mean.
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0, rgba32f) readonly uniform image2DArray g_buffer;
layout(set = 0, binding = 1, rgba32f) readonly uniform image2D shaded;
layout(set = 0, binding = 2, rgba32f) uniform image2D accumulation;
#include "shared/push_constants.h"
#include "shared/chain_record.h"
#include "shared/interleave.h"
// Read only where pc.chains != 0 (engine/render/chain_layer.h).
layout(std430, set = 0, binding = 3) readonly buffer ChainRecords { ChainRecord chains[]; };
layout(push_constant) uniform InterleavePushBlock { InterleavePush pc; };

// Within kInterleaveAlbedo relative (plus kInterleaveMinAlbedo), component by component.
bool close_to(vec3 a, vec3 b) {
    return all(lessThanEqual(abs(a - b), kInterleaveAlbedo * max(a, b) + kInterleaveMinAlbedo));
}
bool close_to(float a, float b) {
    return abs(a - b) <= kInterleaveAlbedo * max(a, b) + kInterleaveMinAlbedo;
}

// Two chains' rough ends (both kChainReceiver) receive alike (interleave.h, "Chains"): the
// G-buffer's surface test on the records' positions and geometric normals, directions towards
// the chains within the same angle, the same closure and path-length limit.
bool compatible_chains(ChainRecord a, ChainRecord b) {
    if (a.max_vpl_length != b.max_vpl_length || a.closure_type != b.closure_type) return false;
    if (dot(a.geometric_normal, b.geometric_normal) < kInterleaveMinCos) return false;
    if (dot(a.wo, b.wo) < kInterleaveMinCos) return false;
    const vec3 d = b.position - a.position;
    if (abs(dot(a.geometric_normal, d)) > kInterleavePlaneSlope * length(d)) return false;
    return close_to(a.base_color, b.base_color) && close_to(a.specular_color, b.specular_color) &&
           close_to(a.metallic, b.metallic) && close_to(a.roughness, b.roughness) &&
           close_to(a.specular, b.specular) && close_to(a.ior, b.ior);
}

void main() {
    const ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    const ivec2 size = ivec2(pc.size);
    if (any(greaterThanEqual(px, size))) return;
    const vec4 p = imageLoad(g_buffer, ivec3(px, 0));
    if (p.w <= 0.0) return;
    const vec3 n = imageLoad(g_buffer, ivec3(px, 2)).xyz;
    vec3 albedo = imageLoad(g_buffer, ivec3(px, 3)).rgb;
    uint state = kChainNone;
    ChainRecord chain;
    if (pc.chains != 0u) {
        chain = chains[px.y * size.x + px.x];
        state = chain.state;
        if (state == kChainBlack) return;  // no VPL light (the shading pass stored 0)
        if (state == kChainReceiver) albedo = chain.base_color;
    }
    const int k = int(pc.interleave);
    const int r = k / 2;
    const bool even = k % 2 == 0;
    const ivec2 centre = max(min(px, size - 1 - ivec2(r)), ivec2(r));
    vec3 sum = vec3(0.0);
    float weights = 0.0;
    for (int dy = -r; dy <= r; ++dy) {
        for (int dx = -r; dx <= r; ++dx) {
            const ivec2 q = centre + ivec2(dx, dy);
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
            vec3 albedo_q = albedo;
            if (q != px && state == kChainReceiver) {
                const ChainRecord cq = chains[q.y * size.x + q.x];
                if (cq.state != kChainReceiver || !compatible_chains(chain, cq)) continue;
                albedo_q = cq.base_color;
            } else if (q != px) {
                // Never an unchained pixel with a chained or black neighbour: their shares are
                // another receiver's.
                if (pc.chains != 0u && chains[q.y * size.x + q.x].state != kChainNone) continue;
                const vec4 pq = imageLoad(g_buffer, ivec3(q, 0));
                if (pq.w != p.w) continue;
                if (dot(n, imageLoad(g_buffer, ivec3(q, 2)).xyz) < kInterleaveMinCos) continue;
                const vec3 d = pq.xyz - p.xyz;
                if (abs(dot(n, d)) > kInterleavePlaneSlope * length(d)) continue;
                albedo_q = imageLoad(g_buffer, ivec3(q, 3)).rgb;
                if (any(greaterThan(abs(albedo_q - albedo),
                                    kInterleaveAlbedo * max(albedo, albedo_q) +
                                        kInterleaveMinAlbedo)))
                    continue;
            }
            const float w = (even && abs(dx) == r ? 0.5 : 1.0) * (even && abs(dy) == r ? 0.5 : 1.0);
            sum += w * imageLoad(shaded, q).rgb / max(albedo_q, vec3(kInterleaveMinAlbedo));
            weights += w;
        }
    }
    vec3 filtered = max(albedo, vec3(kInterleaveMinAlbedo)) * (sum / weights);
    // The chain's throughput is the pixel's own (shading_template.glsl stores the unweighted sum).
    if (state == kChainReceiver) filtered *= chain.throughput;
    imageStore(accumulation, px, vec4(imageLoad(accumulation, px).rgb + filtered, 1.0));
}
