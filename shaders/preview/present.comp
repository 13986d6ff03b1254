#version 460
#extension GL_GOOGLE_include_directive : require
// mvpl preview: the running VPL estimate scale · Σ contributions + the emitted radiance averaged
// over the G-buffers drawn so far (engine/render/emission_sum.h: rgb / a) + the CPU estimators'
// image (clamping compensation and caustics, engine/integrator/cpu_estimators.h), exposed and
// sRGB-encoded exactly as engine/core/image.cpp writes a PNG (linear_to_srgb, then
// round(255 · v)), into the 8-bit display image that is blitted to the window; the HUD's text
// (an RGBA8 image with coverage in alpha, at hud_origin) is blended on top when enabled.
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, rgba32f) readonly uniform image2D accumulation;
layout(set = 0, binding = 1, rgba32f) readonly uniform image2D emission_sum;
layout(set = 0, binding = 2, rgba8) writeonly uniform image2D display;
layout(set = 0, binding = 3, rgba8) readonly uniform image2D hud;
layout(set = 0, binding = 4, rgba32f) readonly uniform image2D cpu_image;

#include "shared/present_push.h"
layout(push_constant) uniform PresentPushBlock { PresentPush params; };

// engine/core/image.cpp's linear_to_srgb, branch for branch.
float linear_to_srgb(float v) {
    if (!(v > 0.0)) return 0.0;
    if (v >= 1.0) return 1.0;
    return v <= 0.0031308 ? 12.92 * v : 1.055 * pow(v, 1.0 / 2.4) - 0.055;
}

void main() {
    const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (p.x >= int(params.width) || p.y >= int(params.height)) return;
    // Nearest neighbour; the identity when the sizes agree (the picture at rest, screenshots).
    const ivec2 q = ivec2((vec2(p) + 0.5) * vec2(params.source_width, params.source_height) /
                          vec2(params.width, params.height));
    const vec3 sum = imageLoad(accumulation, q).rgb;
    const vec4 emission = imageLoad(emission_sum, q);
    const vec3 emitted = emission.rgb / max(emission.a, 1.0);
    vec3 radiance = params.scale * sum + emitted;
    if (params.cpu_image == 1u) radiance += imageLoad(cpu_image, q).rgb;
    if (params.cpu_image == 2u) radiance = imageLoad(cpu_image, q).rgb;  // a view (albedo, …)
    vec3 encoded;
    for (int c = 0; c < 3; ++c) {
        const float v = radiance[c] * params.exposure_scale;
        // The byte the PNG writer would store, as a UNORM value (exact: k / 255).
        encoded[c] = params.linear_target != 0u ? clamp(v, 0.0, 1.0)
                                                : floor(255.0 * linear_to_srgb(v) + 0.5) / 255.0;
    }
    if (params.hud_width > 0u) {
        const ivec2 h = p - ivec2(params.hud_x, params.hud_y);
        if (h.x >= 0 && h.y >= 0 && h.x < int(params.hud_width) && h.y < int(params.hud_height)) {
            const vec4 text = imageLoad(hud, h);
            // A dimmed panel behind the text keeps it readable on a bright image.
            encoded = mix(encoded * 0.35, text.rgb, text.a);
        }
    }
    imageStore(display, p, vec4(encoded, 1.0));
}
