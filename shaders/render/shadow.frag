#version 460
// Shadow cube face: the linear distance from the VPL (r is affine in the position, so its
// perspective-correct interpolation is exact up to rounding); negated where the triangle is of a
// simplified level of detail (w < 0: constant over the triangle, so its sign survives
// interpolation), for the shading pass's allowance (kLodFootprint in shading_template.glsl).
layout(location = 0) in vec4 in_offset;
layout(location = 0) out float out_distance;

void main() {
    out_distance = in_offset.w < 0.0 ? -length(in_offset.xyz) : length(in_offset.xyz);
}
