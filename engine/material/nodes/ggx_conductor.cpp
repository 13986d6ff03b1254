// ggx_conductor: a GGX conductor with Schlick's Fresnel from f0 (the glTF metal).
#include "engine/material/node_graph.h"

namespace mvpl::material::nodes {
namespace {

constexpr std::string_view kInputs[] = {"f0 (rgb)", "roughness"};

ClosureParams evaluate(const NodeContext& c) {
    return make_closure(c.rgb(0), 1.0f, c.scalar(1), 1.0f, Rgb(1.0f), 1.5f);
}

constexpr std::string_view kGlsl = R"(Closure ggx_conductor(vec3 f0, float roughness) {
    return clamp_closure(f0, 1.0, roughness, 1.0, vec3(1.0), 1.5);
}
)";
constexpr std::string_view kGlslDependencies[] = {"clamp_closure"};

std::string call(GlslCallContext& c) {
    return glsl_function_call(c, "ggx_conductor", {c.rgb(0), c.scalar(1)});
}

}  // namespace

extern const NodeKind kGgxConductorNode{.name = "ggx_conductor",
                                        .role = NodeRole::Closure,
                                        .inputs = kInputs,
                                        .closure = evaluate,
                                        .glsl = kGlsl,
                                        .glsl_dependencies = kGlslDependencies,
                                        .glsl_call = call,
                                        .closure_types = closure_type_bit(ClosureType::Conductor)};

}  // namespace mvpl::material::nodes
