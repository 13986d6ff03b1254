// Push constants of the shadow pass (engine/render/shadow_pass.cpp, ShadowPush).
layout(push_constant) uniform ShadowPush {
    vec4 vpl_near;  // xyz: the VPL's position; w: the near distance (geometry closer is ignored)
    uvec4 face;     // x: cube face, +X −X +Y −Y +Z −Z
} pc;
