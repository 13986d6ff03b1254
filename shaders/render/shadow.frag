#version 460
#extension GL_GOOGLE_include_directive : require
// Shadow cube face: the linear distance from the VPL (r is affine in the position, so its
// perspective-correct interpolation is exact up to rounding); negated where the triangle is of a
// simplified level of detail (w < 0: constant over the triangle, so its sign survives
// interpolation), for the shading pass's allowance (kLodFootprint in shading_template.glsl). The
// second channel holds the triangle's plane (shared/shadow_map.h), in the frame of the vertex
// stage's plane point (world axes for cubes, the map's (u, v, w) for orthographic maps): the
// points of neighbouring texels' samples all lie in that plane, so their differences span it.
#include "shared/shadow_map.h"
layout(location = 0) in vec4 in_offset;
layout(location = 6) in vec3 in_plane_point;
layout(location = 0) out vec2 out_texel;

void main() {
    const vec3 n = cross(dFdx(in_plane_point), dFdy(in_plane_point));
    const float r = length(in_offset.xyz);
    out_texel = vec2(in_offset.w < 0.0 ? -r : r, occluder_plane_code(n.x, n.y, n.z));
}
