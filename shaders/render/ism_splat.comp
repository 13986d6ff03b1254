#version 460
#extension GL_GOOGLE_include_directive : require
// Imperfect shadow maps, splat (Ritschel et al. 2008, section 3; engine/render/ism_pass.h): one
// invocation per scene point writes, for every VPL of the batch, the point's distance into the
// texels of the VPL's cube that its disc covers, keeping the nearest by atomicMin on the float's
// bits (positive floats order as their bits do). The cost is points × VPLs, whatever the
// triangle count.
layout(local_size_x = 64) in;
#include "shared/ism.h"
layout(std430, set = 0, binding = 0) readonly buffer Points { IsmPoint points[]; };
layout(std430, set = 0, binding = 1) readonly buffer Vpls { IsmVpl vpls[]; };
layout(std430, set = 0, binding = 2) buffer Depths { uint depths[]; };
layout(push_constant) uniform IsmPushBlock { IsmPush pc; };

// A point stands for a disc of its surface, so it stores what a rasteriser would store for that
// surface in its texel: the distance along the texel's centre direction w_c to the point's
// tangent plane, n·(x − p)/(n·w_c), which is the value the shading pass's receiver-plane test
// (shading_template.glsl, visibility()) computes for a receiver on that surface. A distance
// pushed back by a slope bias instead let light through one-plane walls (two-room scene: mean
// 2.2× the reference; docs/results.md, "Imperfect shadow maps"). Where w_c runs nearly parallel
// to the plane, or the plane distance strays from the point's own (both as the shading pass
// rejects them), the point's distance d.
//
// Each point is a disc of radius IsmPoint::radius (twice its share of the area, ism_points.h),
// splatted into every texel of its face whose centre ray meets the disc, up to kMaxSplatReach
// texels from its own: a point-sized splat let the points behind a near wall through the gaps
// between the wall's (two-room scene). Pull-push fills what remains.
const float kMaxSplatReach = 2.0;

void main() {
    const uint point = gl_GlobalInvocationID.x;
    if (point >= pc.points) return;
    const IsmPoint q = points[point];
    const float res = float(pc.resolution);
    // One point against every VPL of the batch: the VPL index is the same in every lane, and
    // lavapipe pays per workgroup (a dispatch per point and VPL ran 10 % slower).
    for (uint v = 0u; v < pc.vpls; ++v) {
        const IsmVpl vpl = vpls[v];
        const vec3 r = q.position - vpl.position;
        const float d = length(r);
        if (!(d > vpl.near_distance)) continue;
        if (vpl.hemisphere != 0u && dot(vpl.normal, r) <= 0.0) continue;
        const vec3 w = r / d;
        // The texel of direction w as the shading pass finds it (shading_template.glsl,
        // cube_texel: Vulkan's cube face selection, faces +X −X +Y −Y +Z −Z), without
        // branches: lavapipe runs every side of a divergent one.
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
        const vec2 cell = clamp(floor(st * res), vec2(0.0), vec2(res - 1.0));
        // The face's axes (M, S, T) with s_c = S·w, t_c = T·w, |m_a| = M·w.
        vec3 m_axis = vec3(0.0);
        m_axis[axis] = sign;
        const vec3 s_axis = x_major ? vec3(0.0, 0.0, -sign)
                                    : (y_major ? vec3(1.0, 0.0, 0.0) : vec3(sign, 0.0, 0.0));
        const vec3 t_axis = y_major ? vec3(0.0, 0.0, sign) : vec3(0.0, -1.0, 0.0);
        const float normal_w = abs(dot(q.normal, w));
        // The disc's radius in texels: an angle δ/d moves the face coordinate s_c/|m_a| by up to
        // δ/(d · m_a²), and a texel is 2/res of it.
        const float reach = q.radius / (d * a[axis] * a[axis]) * res * 0.5;
        const int k = int(min(ceil(reach - 0.5), kMaxSplatReach));
        const uint base = (6u * vpl.slot.x + face) * pc.resolution;
        for (int dy = -k; dy <= k; ++dy) {
            for (int dx = -k; dx <= k; ++dx) {
                const vec2 c = cell + vec2(dx, dy);
                if (any(lessThan(c, vec2(0.0))) || any(greaterThanEqual(c, vec2(res)))) continue;
                const vec2 centre = (c + 0.5) / res * 2.0 - 1.0;
                const vec3 wc = normalize(m_axis + centre.x * s_axis + centre.y * t_axis);
                const float along = dot(q.normal, wc);
                const float d_plane = dot(q.normal, r) / along;
                const bool plane =
                    abs(along) > 0.05 * normal_w && d_plane > 0.5 * d && d_plane < 2.0 * d;
                // Other texels than the point's own only where their centre ray meets the disc.
                const bool own = dx == 0 && dy == 0;
                if (!own && !(plane && distance(wc * d_plane, r) <= q.radius)) continue;
                const float stored = plane ? d_plane : d;
                const uvec2 t = uvec2(c);
                atomicMin(depths[(base + t.y) * pc.resolution + t.x], floatBitsToUint(stored));
            }
        }
    }
}
