#version 460
#extension GL_GOOGLE_include_directive : require
// Orthographic shadow map of a directional VPL (engine/render/directional_frame.h): map
// coordinates (u, v) / extent → ndc, reversed depth 1 − w / depth so that the surface nearest to
// the light wins, and w (the distance along the direction of travel from the map's near plane)
// handed to shadow.frag as the length of a vector.
#include "shared/push_constants.h"
layout(push_constant) uniform OrthoPushBlock { OrthoPush pc; };

layout(location = 0) in vec3 in_position;
layout(location = 0) out vec4 out_offset;
// The point in the frame whose planes the map's second channel holds (shadow.frag): the map's
// (u, v, w), in which ortho_lookup.glsl intersects them.
layout(location = 6) out vec3 out_plane_point;
#ifdef MVPL_MASKED
// The alpha-tested pipeline of scenes with masked materials (shadow_masked.frag): extents.z is
// the material of the draw.
layout(location = 1) in vec4 in_uv;
layout(location = 2) in vec4 in_color;
layout(location = 1) out vec4 out_uv;
layout(location = 2) out vec4 out_color;
layout(location = 3) flat out uint out_material;
layout(location = 4) flat out uint out_seed;
layout(location = 5) out vec3 out_position;
#endif

void main() {
    const float u = dot(in_position, pc.u_origin.xyz) - pc.u_origin.w;
    const float v = dot(in_position, pc.v_origin.xyz) - pc.v_origin.w;
    const float w = dot(in_position, pc.dir_origin.xyz) - pc.dir_origin.w;
    out_plane_point = vec3(u, v, w);
#ifdef MVPL_MASKED
    out_offset = vec4(w, 0.0, 0.0, 1.0);
#else
    // extents.z: 1 for a simplified level of detail (shadow.frag negates its distances).
    out_offset = vec4(w, 0.0, 0.0, pc.extents.z > 0.5 ? -1.0 : 1.0);
#endif
#ifdef MVPL_MASKED
    out_uv = in_uv;
    out_color = in_color;
    out_material = uint(pc.extents.z);
    out_seed = uint(pc.extents.w);
    out_position = in_position;
#endif
    gl_Position = vec4(2.0 * u / pc.extents.x - 1.0, 2.0 * v / pc.extents.x - 1.0,
                       1.0 - w / pc.extents.y, 1.0);
}
