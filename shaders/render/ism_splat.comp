#version 460
#extension GL_GOOGLE_include_directive : require
// Imperfect shadow maps, splat (Ritschel et al. 2008, section 3; engine/render/ism_pass.h): one
// invocation per scene point writes, for every VPL of the batch, the point's distance into the
// texel of the VPL's cube that holds its direction, keeping the nearest by atomicMin on the float's bits (positive
// floats order as their bits do). The cost is points × VPLs, whatever the triangle count.
layout(local_size_x = 64) in;
#include "shared/ism.h"
layout(std430, set = 0, binding = 0) readonly buffer Points { IsmPoint points[]; };
layout(std430, set = 0, binding = 1) readonly buffer Vpls { IsmVpl vpls[]; };
layout(std430, set = 0, binding = 2) buffer Depths { uint depths[]; };
layout(push_constant) uniform IsmPushBlock { IsmPush pc; };

// A point stands for a disc of the surface, so its distance is pushed back by the spread of the
// receiver-plane test's own surface within a texel: the shading pass (shading_template.glsl,
// visibility()) compares with the distance along the texel's centre direction and allows one
// footprint d·τ; the surface's other points in that texel lie up to 0.71 τ · tan θ footprints
// nearer (half a texel diagonal, θ the angle between the point's normal and the direction).
const float kSlopeBias = 1.0;
const float kMaxSlope = 4.0;

void main() {
    const uint point = gl_GlobalInvocationID.x;
    if (point >= pc.points) return;
    const IsmPoint q = points[point];
    const float res = float(pc.resolution);
    // One point against every VPL of the batch: the VPL index is the same in every lane, and
    // lavapipe pays per workgroup (a dispatch per point and VPL ran 2–3× slower).
    for (uint v = 0u; v < pc.vpls; ++v) {
        const IsmVpl vpl = vpls[v];
        const vec3 r = q.position - vpl.position;
        const float d = length(r);
        if (!(d > vpl.near_distance)) continue;
        if (vpl.hemisphere != 0u && dot(vpl.normal, r) <= 0.0) continue;
        const vec3 w = r / d;
        // The texel of direction w as the shading pass finds it (shading_template.glsl,
        // cube_texel: Vulkan's cube face selection, faces +X −X +Y −Y +Z −Z), without branches:
        // lavapipe runs every side of a divergent one.
        const vec3 a = abs(w);
        const bool x_major = a.x >= a.y && a.x >= a.z;
        const bool y_major = !x_major && a.y >= a.z;
        const uint axis = x_major ? 0u : (y_major ? 1u : 2u);
        const bool negative = w[axis] < 0.0;
        const uint face = 2u * axis + (negative ? 1u : 0u);
        // (s_c, t_c) per major axis: x: (∓z, −y), y: (x, ±z), z: (±x, −y).
        const float sign = negative ? -1.0 : 1.0;
        const vec2 sc = x_major ? vec2(-sign * w.z, -w.y)
                                : (y_major ? vec2(w.x, sign * w.z) : vec2(sign * w.x, -w.y));
        const vec2 st = sc / a[axis] * 0.5 + 0.5;
        const uvec2 texel = uvec2(clamp(floor(st * res), vec2(0.0), vec2(res - 1.0)));
        const float c = abs(dot(q.normal, w));
        const float tan_p = min(sqrt(max(0.0, 1.0 - c * c)) / max(c, 1e-6), kMaxSlope);
        const float stored = d * (1.0 + kSlopeBias * (2.0 / res) * tan_p);
        const uint index =
            ((6u * vpl.slot.x + face) * pc.resolution + texel.y) * pc.resolution + texel.x;
        atomicMin(depths[index], floatBitsToUint(stored));
    }
}
