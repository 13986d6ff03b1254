// metal_rough: the glTF metallic-roughness mix of conductor and dielectric-over-diffuse; any
// closure type where the metallic input varies.
#include "engine/material/node_graph.h"

namespace mvpl::material::nodes {
namespace {

constexpr std::string_view kInputs[] = {
    "base colour (rgb)", "metallic", "roughness", "specular", "specular colour (rgb)", "ior"};

ClosureParams evaluate(const NodeContext& c) {
    return make_closure(c.rgb(0), c.scalar(1), c.scalar(2), c.scalar(3), c.rgb(4), c.scalar(5));
}

constexpr std::string_view kGlsl =
    R"(Closure metal_rough(vec3 base_color, float metallic, float roughness, float specular,
                    vec3 specular_color, float ior) {
    return clamp_closure(base_color, metallic, roughness, specular, specular_color, ior);
}
)";
constexpr std::string_view kGlslDependencies[] = {"clamp_closure"};

std::string call(GlslCallContext& c) {
    return glsl_function_call(
        c, "metal_rough", {c.rgb(0), c.scalar(1), c.scalar(2), c.scalar(3), c.rgb(4), c.scalar(5)});
}

}  // namespace

extern const NodeKind kMetalRoughNode{.name = "metal_rough",
                                      .role = NodeRole::Closure,
                                      .inputs = kInputs,
                                      .closure = evaluate,
                                      .glsl = kGlsl,
                                      .glsl_dependencies = kGlslDependencies,
                                      .glsl_call = call,
                                      .closure_types = (1u << kClosureTypeCount) - 1u};

}  // namespace mvpl::material::nodes
