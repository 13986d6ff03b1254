#pragma once
// The GLSL functions generated code may require by name: the shared helpers of the closures
// (Fresnel, GGX, the closure types' evaluation, the Closure and SurfacePoint structs), defined
// here, and each node kind's own function (NodeKind::glsl, nodes/*.cpp), each declaring its
// dependencies. GlslModule (material_codegen.h) emits what a scene needs, dependencies first and
// each once — Mitsuba 0.5's Shader::putDependencies/generateCode, but by function rather than
// by node instance, so that two materials with the same node kind share one function.
#include <span>
#include <string_view>

namespace mvpl::material {

struct GlslFunction {
    std::string_view name;
    std::span<const std::string_view> dependencies;
    std::string_view code;
};

// nullptr when there is no such function.
const GlslFunction* find_glsl_function(std::string_view name);

}  // namespace mvpl::material
