#version 460
// The material pass of the G-buffer: for scenes whose material graphs read image textures, a
// compute shader re-resolves every covered pixel's graph with the textures bound (the G-buffer's
// graphics pipeline has no descriptor sets) and overwrites the closure, emission and shading
// normal layers. Generated per scene by engine/render/shader_program.cpp.
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0, rgba32f) uniform image2DArray g_buffer;
//@insert bindings
#include "shared/push_constants.h"
layout(push_constant) uniform MaterialPushBlock { MaterialPush pc; };
//@insert materials

void main() {
    const ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(px), pc.size))) return;
    const vec4 position = imageLoad(g_buffer, ivec3(px, 0));
    if (position.w <= 0.0) return;
    const uint material = uint(position.w + 0.5) - 1u;
    const vec4 ns_flags = imageLoad(g_buffer, ivec3(px, 1));
    const vec4 ng_metallic = imageLoad(g_buffer, ivec3(px, 2));
    const vec4 uv = imageLoad(g_buffer, ivec3(px, 6));
    const vec4 tangent = imageLoad(g_buffer, ivec3(px, 7));
    const uint flags = uint(ns_flags.w);
    const bool front = (flags & 1u) != 0u;
    // reference::make_shading_point: a back face of a double-sided material resolves its graph
    // with the flipped normal; the layer keeps the unflipped convention of the shading pass.
    const float side = !front && (flags & 2u) != 0u ? -1.0 : 1.0;
    SurfacePoint s;
    s.uv0 = uv.xy;
    s.uv1 = uv.zw;
    s.color = vec4(1.0);
//@if color_handoff
    s.color = imageLoad(g_buffer, ivec3(px, 4));  // COLOR_0, until overwritten (g_buffer.frag)
//@endif
    s.n = side * ns_flags.xyz;
    s.t = tangent.xyz;
    s.b = tangent.w * cross(s.n, s.t);
    Closure c;
    vec3 emitted;
    vec3 n;
    resolve_material(material, s, c, emitted, n);
    const float new_flags = float((flags & 3u) + 4u * c.type);
    imageStore(g_buffer, ivec3(px, 1), vec4(side * n, new_flags));
    imageStore(g_buffer, ivec3(px, 2), vec4(ng_metallic.xyz, c.metallic));
    imageStore(g_buffer, ivec3(px, 3), vec4(c.base_color, c.roughness));
    imageStore(g_buffer, ivec3(px, 4), vec4(c.specular_color, c.specular));
    imageStore(g_buffer, ivec3(px, 5), vec4(front ? emitted : vec3(0.0), c.ior));
}
