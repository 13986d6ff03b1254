#version 460
#extension GL_GOOGLE_include_directive : require
// Adds the G-buffer's emitted radiance (front faces only, as the G-buffer stores it), or the
// environment where no surface covers the pixel, and what the pixel's specular chain met, into the
// running sum over the G-buffers of a progressive render, and one to the count in alpha: the
// resolve and the preview show rgb / a, the emission seen directly averaged over the sub-pixel
// positions drawn (engine/render/emission_sum.h).
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0, rgba32f) readonly uniform image2DArray g_buffer;
layout(set = 0, binding = 1, rgba32f) uniform image2D emission_sum;
// The environment seen through each pixel's centre (EmissionSum::set_background), where no
// surface covers it (position.w = 0); read only with kEmissionBackground.
layout(set = 0, binding = 2, rgba32f) readonly uniform image2D background;
#include "shared/chain_record.h"
// The specular chains of this position (engine/render/chain_layer.h), one record per pixel: the
// emitted radiance they met; read only with kEmissionChains.
layout(set = 0, binding = 3, std430) readonly buffer ChainRecords { ChainRecord chain_records[]; };
#include "shared/push_constants.h"
layout(push_constant) uniform EmissionPushBlock { EmissionPush pc; };

void main() {
    const ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(px), pc.size))) return;
    vec3 emitted = imageLoad(g_buffer, ivec3(px, int(pc.layer))).rgb;
    if ((pc.flags & kEmissionBackground) != 0u && imageLoad(g_buffer, ivec3(px, 0)).w <= 0.0)
        emitted = imageLoad(background, px).rgb;
    if ((pc.flags & kEmissionChains) != 0u)
        emitted += chain_records[uint(px.y) * pc.size.x + uint(px.x)].emitted;
    imageStore(emission_sum, px, imageLoad(emission_sum, px) + vec4(emitted, 1.0));
}
