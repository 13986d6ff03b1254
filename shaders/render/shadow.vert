#version 460
#extension GL_GOOGLE_include_directive : require
// Shadow cube face: projects r = p − vpl onto face pc.face.x exactly as Vulkan's cube sampling
// maps a direction to a texel (spec, "Cube Map Face Selection": s_c, t_c and the major axis m_a),
// so that the texel a direction is rendered into is the texel textureLod reads for it:
// clip = (s_c, t_c, near, m_a), i.e. ndc = (s_c, t_c) / |m_a| and reversed depth near / m_a.
#include "shared/push_constants.h"
layout(push_constant) uniform ShadowPushBlock { ShadowPush pc; };

layout(location = 0) in vec3 in_position;
layout(location = 0) out vec4 out_offset;  // w: −1 for a simplified level (face.w)
// The point in the frame whose planes the map's second channel holds (shadow.frag): world axes.
layout(location = 6) out vec3 out_plane_point;
#ifdef MVPL_MASKED
// The alpha-tested pipeline of scenes with masked materials (shadow_masked.frag): face.y is the
// material of the draw.
layout(location = 1) in vec4 in_uv;
layout(location = 2) in vec4 in_color;
layout(location = 1) out vec4 out_uv;
layout(location = 2) out vec4 out_color;
layout(location = 3) flat out uint out_material;
layout(location = 4) flat out uint out_seed;
layout(location = 5) out vec3 out_position;
#endif

void main() {
    const vec3 r = in_position - pc.vpl_near.xyz;
    vec3 m;  // (s_c, t_c, m_a)
    switch (pc.face.x) {
        case 0u: m = vec3(-r.z, -r.y, r.x); break;
        case 1u: m = vec3(r.z, -r.y, -r.x); break;
        case 2u: m = vec3(r.x, r.z, r.y); break;
        case 3u: m = vec3(r.x, -r.z, -r.y); break;
        case 4u: m = vec3(r.x, -r.y, r.z); break;
        default: m = vec3(-r.x, -r.y, -r.z); break;
    }
    out_offset = vec4(r, pc.face.w != 0u ? -1.0 : 1.0);
    out_plane_point = r;
#ifdef MVPL_MASKED
    out_uv = in_uv;
    out_color = in_color;
    out_material = pc.face.y;
    out_seed = pc.face.z;
    out_position = in_position;
#endif
    gl_Position = vec4(m.x, m.y, pc.vpl_near.w, m.z);
}
