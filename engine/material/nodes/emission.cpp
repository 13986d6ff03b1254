// emission: the emitted radiance, colour (rgb) times the strength in Node::value.x
// (KHR_materials_emissive_strength).
#include "engine/material/node_graph.h"

namespace mvpl::material::nodes {
namespace {

constexpr std::string_view kInputs[] = {"colour (rgb)"};

Vec4 evaluate(const NodeContext& c) {
    return Vec4(Vec3(c.input(0)) * c.node().value.x, 1.0f);
}

constexpr std::string_view kGlsl = R"(vec4 emission(vec4 colour, float strength) {
    return vec4(colour.rgb * strength, 1.0);
}
)";

std::string call(GlslCallContext& c) {
    return glsl_function_call(c, "emission", {c.input(0), glsl_number(c.node().value.x)});
}

}  // namespace

extern const NodeKind kEmissionNode{.name = "emission",
                                    .role = NodeRole::Value,
                                    .inputs = kInputs,
                                    .value = evaluate,
                                    .glsl = kGlsl,
                                    .glsl_call = call};

}  // namespace mvpl::material::nodes
