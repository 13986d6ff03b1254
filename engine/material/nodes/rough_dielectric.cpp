// rough_dielectric: the reflection lobe of a rough dielectric interface, a dielectric layer over a
// black base (KHR_materials_transmission = 1: the transmitted lobe is the graph's CPU-only
// transmission output, graph_from_gltf).
#include "engine/material/node_graph.h"

namespace mvpl::material::nodes {
namespace {

constexpr std::string_view kInputs[] = {"roughness", "specular", "specular colour (rgb)", "ior"};

ClosureParams evaluate(const NodeContext& c) {
    return make_closure(Rgb(0.0f), 0.0f, c.scalar(0), c.scalar(1), c.rgb(2), c.scalar(3));
}

constexpr std::string_view kGlsl =
    R"(// The reflection lobe only: a dielectric layer over a black base (node_graph.h).
Closure rough_dielectric(float roughness, float specular, vec3 specular_color, float ior) {
    return clamp_closure(vec3(0.0), 0.0, roughness, specular, specular_color, ior);
}
)";
constexpr std::string_view kGlslDependencies[] = {"clamp_closure"};

std::string call(GlslCallContext& c) {
    return glsl_function_call(c, "rough_dielectric",
                              {c.scalar(0), c.scalar(1), c.rgb(2), c.scalar(3)});
}

}  // namespace

extern const NodeKind kRoughDielectricNode{
    .name = "rough_dielectric",
    .role = NodeRole::Closure,
    .inputs = kInputs,
    .closure = evaluate,
    .glsl = kGlsl,
    .glsl_dependencies = kGlslDependencies,
    .glsl_call = call,
    .closure_types =
        closure_type_bit(ClosureType::Lambertian) | closure_type_bit(ClosureType::Dielectric)};

}  // namespace mvpl::material::nodes
