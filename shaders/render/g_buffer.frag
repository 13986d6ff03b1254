#version 460
#extension GL_GOOGLE_include_directive : require
// G-buffer: one layer of an RGBA32F array per output (engine/render/g_buffer_layout.h).
#include "g_buffer_push.glsl"

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) flat in vec3 in_face_normal;

layout(location = 0) out vec4 out_position;         // xyz, w = 1 where covered
layout(location = 1) out vec4 out_shading_normal;   // xyz, w = flags (1: front face, 2: 2-sided)
layout(location = 2) out vec4 out_geometric_normal; // winding normal, w = metallic
layout(location = 3) out vec4 out_base_color;       // rgb, w = roughness
layout(location = 4) out vec4 out_specular;         // specular_color, w = specular
layout(location = 5) out vec4 out_emission;         // front face only, w = ior

void main() {
    const vec3 ng = in_face_normal;
    // As trace::make_interaction: the interpolated normal, flipped to the winding normal's side.
    vec3 ns = ng;
    const float len = length(in_normal);
    if (len > 0.0 && !isinf(len)) ns = in_normal / len;
    if (dot(ns, ng) < 0.0) ns = -ns;
    // Counter-clockwise front faces through a y-flipped projection: the winding normal points
    // towards the camera (tests/render check this against a CPU ray cast).
    const bool front = gl_FrontFacing;
    const float flags = (front ? 1.0 : 0.0) + ((pc.material_flags & 1u) != 0u ? 2.0 : 0.0);

    out_position = vec4(in_position, 1.0);
    out_shading_normal = vec4(ns, flags);
    out_geometric_normal = vec4(ng, pc.base_color_metallic.w);
    out_base_color = vec4(pc.base_color_metallic.rgb, pc.emission_roughness.w);
    out_specular = pc.specular_color_specular;
    out_emission = vec4(front ? pc.emission_roughness.rgb : vec3(0.0), pc.ior);
}
