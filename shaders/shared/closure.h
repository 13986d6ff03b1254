// The parameters of a resolved closure, listed once for engine/material/closure.h's ClosureParams
// (C++, with its defaults) and the GLSL struct Closure into which the generated shaders resolve
// materials (engine/material/glsl_library.cpp, entry "Closure"): an X-macro, because the C++
// struct has defaults and Rgb members that the common subset of prelude.h cannot spell.
// F(GLSL type, C++ type, name, C++ default). The order is the GLSL struct's, which the shaders'
// positional Closure(type, ...) constructors rely on (shading_template.glsl).
#ifndef MVPL_SHADERS_SHARED_CLOSURE_H
#define MVPL_SHADERS_SHARED_CLOSURE_H

// clang-format off
#define MVPL_CLOSURE_PARAMS(F)                  \
    F(vec3, Rgb, base_color, Rgb(0.8f))         \
    F(float, float, metallic, 0.0f)             \
    F(vec3, Rgb, specular_color, Rgb(1.0f))     \
    /* KHR_materials_specular factor; 0 removes the dielectric layer */ \
    F(float, float, specular, 1.0f)             \
    /* perceptual (glTF); the GGX alpha is roughness squared */ \
    F(float, float, roughness, 1.0f)            \
    F(float, float, ior, 1.5f)
// clang-format on

#ifdef __cplusplus

// A member of ClosureParams: MVPL_CLOSURE_PARAMS(MVPL_CLOSURE_MEMBER) in the struct's body.
#define MVPL_CLOSURE_MEMBER(glsl, cpp, name, value) cpp name = value;
#define MVPL_CLOSURE_GLSL_MEMBER(glsl, cpp, name, value) "    " #glsl " " #name ";\n"

namespace mvpl::shared {

// The GLSL struct as text, for the code generator that emits it (glsl_library.cpp); the same
// struct as the #else branch below, which a shader that includes this file gets.
inline constexpr char kClosureGlsl[] =
    "// A resolved closure (shaders/shared/closure.h) and its type (closure.h, ClosureType).\n"
    "struct Closure {\n"
    "    uint type;\n" MVPL_CLOSURE_PARAMS(MVPL_CLOSURE_GLSL_MEMBER) "};\n";

}  // namespace mvpl::shared

#else

#define MVPL_CLOSURE_GLSL_MEMBER(glsl, cpp, name, value) glsl name;
struct Closure {
    uint type;  // engine/material/closure.h, ClosureType
    MVPL_CLOSURE_PARAMS(MVPL_CLOSURE_GLSL_MEMBER)
};

#endif

#endif
