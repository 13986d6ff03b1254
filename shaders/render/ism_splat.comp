#version 460
#extension GL_GOOGLE_include_directive : require
// Imperfect shadow maps, splat (Ritschel et al. 2008, section 3; engine/render/ism_pass.h): one
// invocation per (scene point, VPL) writes the point's distance into the texel of the VPL's cube
// that holds its direction, keeping the nearest by atomicMin on the float's bits (positive
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
    const uint v = gl_WorkGroupID.y;
    if (point >= pc.points || v >= pc.vpls) return;
    const IsmVpl vpl = vpls[v];
    const IsmPoint q = points[point];
    const vec3 r = q.position - vpl.position;
    const float d = length(r);
    if (!(d > vpl.near_distance)) return;
    if (vpl.hemisphere != 0u && dot(vpl.normal, r) <= 0.0) return;
    const vec3 w = r / d;
    // The texel of direction w as the shading pass finds it (shading_template.glsl, cube_texel:
    // Vulkan's cube face selection, faces +X −X +Y −Y +Z −Z).
    const vec3 a = abs(w);
    vec3 m;  // (s_c, t_c, |m_a|)
    uint face;
    if (a.x >= a.y && a.x >= a.z) {
        face = w.x < 0.0 ? 1u : 0u;
        m = vec3(w.x < 0.0 ? w.z : -w.z, -w.y, a.x);
    } else if (a.y >= a.z) {
        face = w.y < 0.0 ? 3u : 2u;
        m = vec3(w.x, w.y < 0.0 ? -w.z : w.z, a.y);
    } else {
        face = w.z < 0.0 ? 5u : 4u;
        m = vec3(w.z < 0.0 ? -w.x : w.x, -w.y, a.z);
    }
    const float res = float(pc.resolution);
    const vec2 st = m.xy / m.z * 0.5 + 0.5;
    const uvec2 texel = uvec2(clamp(floor(st * res), vec2(0.0), vec2(res - 1.0)));
    const float c = abs(dot(q.normal, w));
    const float tan_p = min(sqrt(max(0.0, 1.0 - c * c)) / max(c, 1e-6), kMaxSlope);
    const float stored = d * (1.0 + kSlopeBias * (2.0 / res) * tan_p);
    const uint index =
        ((6u * vpl.slot.x + face) * pc.resolution + texel.y) * pc.resolution + texel.x;
    atomicMin(depths[index], floatBitsToUint(stored));
}
