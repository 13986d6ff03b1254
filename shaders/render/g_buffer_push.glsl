// Push constants of the G-buffer pass (engine/render/g_buffer_pass.cpp, GBufferPush): the
// camera and the material of the draw, 120 of the 128 bytes every device guarantees.
layout(push_constant) uniform GBufferPush {
    mat4 view_proj;  // reversed infinite perspective, Vulkan clip space (image row 0 at the top)
    vec4 base_color_metallic;
    vec4 specular_color_specular;
    vec4 emission_roughness;
    float ior;
    uint material_flags;  // bit 0: double-sided
} pc;
