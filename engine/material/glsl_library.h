#pragma once
// The GLSL side of the material nodes: one function per node kind (named as node_name() and as
// its C++ evaluator in node_eval.h), plus the helpers they need, each declaring its
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
