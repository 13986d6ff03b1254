// dielectric_diffuse: a GGX dielectric layer over a Lambertian base (the glTF non-metal); a
// specular input that reaches 0 somewhere leaves the Lambertian base there.
#include "engine/material/node_graph.h"

namespace mvpl::material::nodes {
namespace {

constexpr std::string_view kInputs[] = {"base colour (rgb)", "roughness", "specular",
                                        "specular colour (rgb)", "ior"};

ClosureParams evaluate(const NodeContext& c) {
    return make_closure(c.rgb(0), 0.0f, c.scalar(1), c.scalar(2), c.rgb(3), c.scalar(4));
}

constexpr std::string_view kGlsl =
    R"(Closure dielectric_diffuse(vec3 base_color, float roughness, float specular,
                           vec3 specular_color, float ior) {
    return clamp_closure(base_color, 0.0, roughness, specular, specular_color, ior);
}
)";
constexpr std::string_view kGlslDependencies[] = {"clamp_closure"};

std::string call(GlslCallContext& c) {
    return glsl_function_call(c, "dielectric_diffuse",
                              {c.rgb(0), c.scalar(1), c.scalar(2), c.rgb(3), c.scalar(4)});
}

}  // namespace

extern const NodeKind kDielectricDiffuseNode{
    .name = "dielectric_diffuse",
    .role = NodeRole::Closure,
    .inputs = kInputs,
    .closure = evaluate,
    .glsl = kGlsl,
    .glsl_dependencies = kGlslDependencies,
    .glsl_call = call,
    .closure_types =
        closure_type_bit(ClosureType::Lambertian) | closure_type_bit(ClosureType::Dielectric)};

}  // namespace mvpl::material::nodes
