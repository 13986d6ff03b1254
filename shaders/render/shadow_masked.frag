#version 460
// Shadow maps of scenes that draw alpha-tested materials (glTF alphaMode MASK, or BLEND as hashed
// transparency with a seed per VPL): the distance, as shadow.frag writes it, where the material
// keeps its surface, nothing where it cuts it; the plane beside it, as shadow.frag writes it.
// Generated per scene by engine/render/shadow_pass.cpp: `//@insert materials` holds the masked
// materials' graphs and alpha_cut (engine/material/material_codegen.h).
#include "shared/shadow_map.h"
//@insert bindings
//@insert materials

layout(location = 0) in vec4 in_offset;  // w: +1 (masked meshes are never simplified)
layout(location = 1) in vec4 in_uv;
layout(location = 2) in vec4 in_color;
layout(location = 3) flat in uint in_material;
layout(location = 4) flat in uint in_seed;
layout(location = 5) in vec3 in_position;
layout(location = 6) in vec3 in_plane_point;
layout(location = 0) out vec2 out_texel;

void main() {
    SurfacePoint s;
    s.uv0 = in_uv.xy;
    s.uv1 = in_uv.zw;
    s.color = in_color;
    // Alpha reads no frame (it is base colour: textures, factors, COLOR_0).
    s.t = vec3(1.0, 0.0, 0.0);
    s.b = vec3(0.0, 1.0, 0.0);
    s.n = vec3(0.0, 0.0, 1.0);
    // Derivatives before the discard: the quad's neighbours are undefined after it.
    const vec3 n = cross(dFdx(in_plane_point), dFdy(in_plane_point));
    if (alpha_cut(in_material, s, in_position, in_seed)) discard;
    out_texel = vec2(length(in_offset.xyz), occluder_plane_code(n.x, n.y, n.z));
}
