// mix_node: a + (b − a) · t with t clamped to [0, 1] (a factor outside that range would
// extrapolate). Named mix_node because GLSL's mix is a built-in.
#include <algorithm>

#include "engine/material/node_graph.h"

namespace mvpl::material::nodes {
namespace {

constexpr std::string_view kInputs[] = {"a", "b", "factor (scalar)"};

Vec4 evaluate(const NodeContext& c) {
    const Vec4 a = c.input(0);
    const Vec4 b = c.input(1);
    const float f = std::clamp(c.scalar(2), 0.0f, 1.0f);
    return a + (b - a) * f;
}

constexpr std::string_view kGlsl = R"(vec4 mix_node(vec4 a, vec4 b, float t) {
    const float f = clamp(t, 0.0, 1.0);
    return a + (b - a) * f;
}
)";

std::string call(GlslCallContext& c) {
    return glsl_function_call(c, "mix_node", {c.input(0), c.input(1), c.scalar(2)});
}

}  // namespace

extern const NodeKind kMixNode{.name = "mix_node",
                               .role = NodeRole::Value,
                               .inputs = kInputs,
                               .value = evaluate,
                               .glsl = kGlsl,
                               .glsl_call = call};

}  // namespace mvpl::material::nodes
