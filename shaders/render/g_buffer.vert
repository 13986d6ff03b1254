#version 460
#extension GL_GOOGLE_include_directive : require
// G-buffer: world-space attributes for the fragment shader; the winding normal is per triangle,
// hence flat: Vulkan takes it from the triangle's first vertex, which holds that triangle's
// (engine/render/geometry_vertex.h).
#include "g_buffer_push.glsl"

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec3 in_face_normal;
layout(location = 3) in vec4 in_uv;       // uv0, uv1
layout(location = 4) in vec4 in_tangent;  // ∂p/∂u (unnormalised), w = sign
layout(location = 5) in vec4 in_color;    // COLOR_0, white where the mesh has none

layout(location = 0) out vec3 out_position;
layout(location = 1) out vec3 out_normal;
layout(location = 2) flat out vec3 out_face_normal;
layout(location = 3) out vec4 out_uv;
layout(location = 4) out vec4 out_tangent;
layout(location = 5) out vec4 out_color;

void main() {
    out_position = in_position;
    out_normal = in_normal;
    out_face_normal = in_face_normal;
    out_uv = in_uv;
    out_tangent = in_tangent;
    out_color = in_color;
    gl_Position = pc.view_proj * vec4(in_position, 1.0);
}
