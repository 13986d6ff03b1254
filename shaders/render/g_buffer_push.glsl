// Push constants of the G-buffer pass (engine/render/g_buffer_pass.cpp, GBufferPush): the
// camera and which material the draw uses.
layout(push_constant) uniform GBufferPush {
    mat4 view_proj;  // reversed infinite perspective, Vulkan clip space (image row 0 at the top)
    uint material_flags;  // bit 0: double-sided
    uint material;        // index of the scene material: resolve_material's argument
} pc;
