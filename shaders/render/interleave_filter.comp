#version 460
#extension GL_GOOGLE_include_directive : require
// The geometry-aware filter of interleaved sampling (shaders/shared/interleave.h): adds to each
// covered pixel's accumulation the weighted mean of the interleaved batch sums (each K² times its
// class's share of the batch) over the neighbours on the same surface.
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0, rgba32f) readonly uniform image2DArray g_buffer;
layout(set = 0, binding = 1, rgba32f) readonly uniform image2D shaded;
layout(set = 0, binding = 2, rgba32f) uniform image2D accumulation;
#include "shared/push_constants.h"
#include "shared/interleave.h"
layout(push_constant) uniform InterleavePushBlock { InterleavePush pc; };

void main() {
    const ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    const ivec2 size = ivec2(pc.size);
    if (any(greaterThanEqual(px, size))) return;
    const vec4 p = imageLoad(g_buffer, ivec3(px, 0));
    if (p.w <= 0.0) return;
    const vec3 n = imageLoad(g_buffer, ivec3(px, 2)).xyz;
    const vec3 albedo = imageLoad(g_buffer, ivec3(px, 3)).rgb;
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
            if (q != px) {
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
    const vec3 filtered = max(albedo, vec3(kInterleaveMinAlbedo)) * (sum / weights);
    imageStore(accumulation, px, vec4(imageLoad(accumulation, px).rgb + filtered, 1.0));
}
