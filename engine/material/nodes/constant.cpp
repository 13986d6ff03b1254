// constant: a literal vec4 (Node::value). It has no GLSL function: the generated code writes the
// literal (and the closure nodes' scalar inputs as plain floats, material_codegen.cpp).
#include "engine/material/node_graph.h"

namespace mvpl::material::nodes {
namespace {

Vec4 evaluate(const NodeContext& c) {
    return c.node().value;
}

std::string call(GlslCallContext& c) {
    return glsl_vec4(c.node().value);
}

}  // namespace

extern const NodeKind kConstantNode{
    .name = "constant", .role = NodeRole::Value, .value = evaluate, .glsl_call = call};

}  // namespace mvpl::material::nodes
