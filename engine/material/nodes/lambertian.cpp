// lambertian: a pure Lambertian with the base colour as albedo.
#include "engine/material/node_graph.h"

namespace mvpl::material::nodes {
namespace {

constexpr std::string_view kInputs[] = {"base colour (rgb)"};

ClosureParams evaluate(const NodeContext& c) {
    return make_closure(c.rgb(0), 0.0f, 1.0f, 0.0f, Rgb(1.0f), 1.5f);
}

constexpr std::string_view kGlsl = R"(Closure lambertian(vec3 base_color) {
    return clamp_closure(base_color, 0.0, 1.0, 0.0, vec3(1.0), 1.5);
}
)";
constexpr std::string_view kGlslDependencies[] = {"clamp_closure"};

std::string call(GlslCallContext& c) {
    return glsl_function_call(c, "lambertian", {c.rgb(0)});
}

}  // namespace

extern const NodeKind kLambertianNode{.name = "lambertian",
                                      .role = NodeRole::Closure,
                                      .inputs = kInputs,
                                      .closure = evaluate,
                                      .glsl = kGlsl,
                                      .glsl_dependencies = kGlslDependencies,
                                      .glsl_call = call,
                                      .closure_types = closure_type_bit(ClosureType::Lambertian)};

}  // namespace mvpl::material::nodes
