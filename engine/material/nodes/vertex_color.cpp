// vertex_color: COLOR_0 times the factor in Node::value.
#include "engine/material/node_graph.h"

namespace mvpl::material::nodes {
namespace {

Vec4 evaluate(const NodeContext& c) {
    return c.node().value * c.point().color;
}

constexpr std::string_view kGlsl = R"(vec4 vertex_color(vec4 factor, vec4 color) {
    return factor * color;
}
)";

std::string call(GlslCallContext& c) {
    return glsl_function_call(c, "vertex_color", {glsl_vec4(c.node().value), "s.color"});
}

}  // namespace

extern const NodeKind kVertexColorNode{.name = "vertex_color",
                                       .role = NodeRole::Value,
                                       .value = evaluate,
                                       .glsl = kGlsl,
                                       .glsl_call = call};

}  // namespace mvpl::material::nodes
