#version 460
// Shadow cube face: the linear distance from the VPL (r is affine in the position, so its
// perspective-correct interpolation is exact up to rounding).
layout(location = 0) in vec3 in_offset;
layout(location = 0) out float out_distance;

void main() {
    out_distance = length(in_offset);
}
