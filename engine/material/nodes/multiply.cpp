// multiply: a · b per component, e.g. the glTF base colour times COLOR_0 (gltf_graph.cpp).
#include "engine/material/node_graph.h"

namespace mvpl::material::nodes {
namespace {

constexpr std::string_view kInputs[] = {"a", "b"};

Vec4 evaluate(const NodeContext& c) {
    return c.input(0) * c.input(1);
}

constexpr std::string_view kGlsl = R"(vec4 multiply(vec4 a, vec4 b) {
    return a * b;
}
)";

std::string call(GlslCallContext& c) {
    return glsl_function_call(c, "multiply", {c.input(0), c.input(1)});
}

}  // namespace

extern const NodeKind kMultiplyNode{.name = "multiply",
                                    .role = NodeRole::Value,
                                    .inputs = kInputs,
                                    .value = evaluate,
                                    .glsl = kGlsl,
                                    .glsl_call = call};

}  // namespace mvpl::material::nodes
