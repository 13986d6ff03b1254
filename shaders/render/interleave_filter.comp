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

// The pixel's own chain record, the fields compatible_chain() compares. The states come from the
// shaded image's alpha and a neighbour's fields are read one by one where they are compared:
// copying whole records per neighbour cost lavapipe 3 ms per VPL at 512² on assets/glossy
// (batch 32), more than the interleaved shading itself.
struct ChainEnd {
    vec3 position;
    vec3 ng;
    vec3 wo;
    vec3 base_color;
    vec3 specular_color;
    float metallic;
    float roughness;
    float specular;
    float ior;
    uint closure_type;
    uint max_vpl_length;
};

// Whether chain record j (a neighbour tagged kChainReceiver) receives as `a` does
// (interleave.h, "Chains"): the G-buffer's surface test on the records' positions and geometric
// normals, the same closure and path-length limit, and but for a Lambertian end directions
// towards the chains within the same angle. Each field is read from the buffer where it is
// compared.
bool compatible_chain(ChainEnd a, uint j) {
    if (a.max_vpl_length != chains[j].max_vpl_length || a.closure_type != chains[j].closure_type)
        return false;
    if (dot(a.ng, chains[j].geometric_normal) < kInterleaveMinCos) return false;
    const vec3 d = chains[j].position - a.position;
    if (abs(dot(a.ng, d)) > kInterleavePlaneSlope * length(d)) return false;
    if (!close_to(a.base_color, chains[j].base_color)) return false;
    // A Lambertian end (closure type 0) reflects base_color / π whatever wo and the rest.
    if (a.closure_type == 0u) return true;
    if (dot(a.wo, chains[j].wo) < kInterleaveMinCos) return false;
    return close_to(a.specular_color, chains[j].specular_color) &&
           close_to(a.metallic, chains[j].metallic) && close_to(a.roughness, chains[j].roughness) &&
           close_to(a.specular, chains[j].specular) && close_to(a.ior, chains[j].ior);
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
    ChainEnd chain;
    vec3 throughput = vec3(1.0);
    if (pc.chains != 0u) {
        const uint i = uint(px.y * size.x + px.x);
        // The shading pass tags each pixel's share with 1 + its chain's state (alpha).
        state = uint(imageLoad(shaded, px).a) - 1u;
        if (state == kChainBlack) return;  // no VPL light (the shading pass stored 0)
        if (state == kChainReceiver) {
            chain = ChainEnd(chains[i].position, chains[i].geometric_normal, chains[i].wo,
                             chains[i].base_color, chains[i].specular_color, chains[i].metallic,
                             chains[i].roughness, chains[i].specular, chains[i].ior,
                             chains[i].closure_type, chains[i].max_vpl_length);
            throughput = chains[i].throughput;
            albedo = chain.base_color;
        }
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
            if (q != px && pc.chains != 0u) {
                // Never a chained pixel with an unchained or black neighbour, nor the other way
                // round: their shares are another receiver's. (An uncovered neighbour's tag is a
                // stale one; its record, all zeros, or its G-buffer fails the tests below.)
                if (uint(imageLoad(shaded, q).a) - 1u != state) continue;
                if (state == kChainReceiver) {
                    const uint j = uint(q.y * size.x + q.x);
                    if (!compatible_chain(chain, j)) continue;
                    albedo_q = chains[j].base_color;
                }
            }
            if (q != px && state == kChainNone) {
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
    if (state == kChainReceiver) filtered *= throughput;
    imageStore(accumulation, px, vec4(imageLoad(accumulation, px).rgb + filtered, 1.0));
}
