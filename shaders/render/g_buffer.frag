#version 460
// G-buffer: one layer of an RGBA32F array per output (engine/render/g_buffer_pass.h). Generated
// per scene by engine/render/shader_program.cpp: `//@insert materials` becomes the scene's
// material graphs as GLSL (engine/material/material_codegen.h), one function per material.
//@insert push
//@insert bindings
//@insert materials

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) flat in vec3 in_face_normal;
layout(location = 3) in vec4 in_uv;
layout(location = 4) in vec4 in_tangent;
layout(location = 5) in vec4 in_color;

layout(location = 0) out vec4 out_position;         // xyz, w = 1 + material index where covered
layout(location = 1) out vec4 out_shading_normal;   // xyz, w = flags (1: front, 2: 2-sided, 4·closure type)
layout(location = 2) out vec4 out_geometric_normal; // winding normal, w = metallic
layout(location = 3) out vec4 out_base_color;       // rgb, w = roughness
layout(location = 4) out vec4 out_specular;         // specular_color, w = specular
layout(location = 5) out vec4 out_emission;         // front face only, w = ior
layout(location = 6) out vec4 out_uv;               // uv0, uv1
layout(location = 7) out vec4 out_tangent;          // unit tangent ⟂ ns, w = sign

// A tangent frame around n (engine/core/math.h, Frame(n)): the fallback of a degenerate tangent.
void frame_around(vec3 n, out vec3 s, out vec3 t) {
    const float sgn = n.z >= 0.0 ? 1.0 : -1.0;
    const float a = -1.0 / (sgn + n.z);
    const float b = n.x * n.y * a;
    s = vec3(1.0 + sgn * n.x * n.x * a, sgn * b, -sgn * n.x);
    t = vec3(b, sgn + n.y * n.y * a, -n.y);
}

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

    // As trace::make_interaction: the tangent Gram-Schmidt-ed against ns, else Frame(ns).s; and
    // as reference::make_shading_point the bitangent sign · ns × t.
    vec3 fs;
    vec3 ft;
    frame_around(ns, fs, ft);
    vec3 tangent = in_tangent.xyz - ns * dot(ns, in_tangent.xyz);
    const float tlen = length(tangent);
    tangent = tlen > 1e-20 && !isinf(tlen) ? tangent / tlen : fs;
    const float sign = in_tangent.w < 0.0 ? -1.0 : 1.0;
    SurfacePoint s;
    s.uv0 = in_uv.xy;
    s.uv1 = in_uv.zw;
    s.color = in_color;
    s.n = ns;
    s.t = tangent;
    s.b = sign * cross(ns, tangent);
//@if alpha_tested
    // glTF alphaMode MASK and BLEND (material_codegen.h, alpha_cut): what lies behind shows.
    if (alpha_cut(pc.material, s, in_position, pc.seed)) discard;
//@endif
    Closure c;
    vec3 emitted;
    vec3 n;
    resolve_material(pc.material, s, c, emitted, n);

    const float flags = (front ? 1.0 : 0.0) + ((pc.material_flags & 1u) != 0u ? 2.0 : 0.0) +
                        4.0 * float(c.type);
    out_position = vec4(in_position, 1.0 + float(pc.material));
    out_shading_normal = vec4(n, flags);
    out_geometric_normal = vec4(ng, c.metallic);
    out_base_color = vec4(c.base_color, c.roughness);
    out_specular = vec4(c.specular_color, c.specular);
    out_emission = vec4(front ? emitted : vec3(0.0), c.ior);
    out_uv = in_uv;
    out_tangent = vec4(tangent, sign);
//@if color_handoff
    // The material pass recomputes this layer (every covered pixel's): until then it carries
    // COLOR_0 to that pass, which the fragment stage has and it has not.
    out_specular = in_color;
//@endif
}
