// spec_gloss: KHR_materials_pbrSpecularGlossiness as the dielectric-over-diffuse closure. The
// extension's BRDF inputs ("Specular - Glossiness"):
//     c_diff = diffuse.rgb · (1 − max(specular.r, specular.g, specular.b)),
//     F0 = specular,  α = (1 − glossiness)²,
// with glTF's Schlick Fresnel F = F0 + (1 − F0)(1 − |v·h|)^5 (F90 = 1). The closure of
// dielectric_diffuse.h has F0 = min(f0_from_ior(ior) · specular_color, 1) · specular and
// F90 = specular, so specular = 1 and ior = 0 (f0_from_ior(0) = 1, KHR_materials_specular's own
// reading of spec-gloss) give F0 = specular colour and F90 = 1 exactly; roughness = 1 − glossiness
// (α = roughness², microfacet.h); base colour = c_diff. The one difference from the extension's
// BRDF is the closure's own: its diffuse base is weighted by the macro-surface Fresnel
// transmittance both ways instead of (1 − F(v·h)) (dielectric_diffuse.h says why), as for every
// glTF dielectric here.

#include "engine/material/node_graph.h"

namespace mvpl::material::nodes {
namespace {

constexpr std::string_view kInputs[] = {"diffuse (rgb)", "specular (rgb)", "glossiness"};

// The specular colour limited to [0, 1] (the extension's range; NaN to 0) before max() reads it,
// as clamp_to_valid_ranges limits a base colour.
using shared::math::clamp_unit;

ClosureParams evaluate(const NodeContext& c) {
    const Rgb s = c.rgb(1);
    const Rgb f0(clamp_unit(s.r), clamp_unit(s.g), clamp_unit(s.b));
    const Rgb c_diff = c.rgb(0) * (1.0f - max_component(f0));
    return make_closure(c_diff, 0.0f, 1.0f - c.scalar(2), 1.0f, f0, 0.0f);
}

constexpr std::string_view kGlsl =
    R"(Closure spec_gloss(vec3 diffuse, vec3 specular, float glossiness) {
    const vec3 f0 = vec3(clamp_unit(specular.r), clamp_unit(specular.g), clamp_unit(specular.b));
    const vec3 c_diff = diffuse * (1.0 - max_component(f0));
    return clamp_closure(c_diff, 0.0, 1.0 - glossiness, 1.0, f0, 0.0);
}
)";
constexpr std::string_view kGlslDependencies[] = {"clamp_closure", "max_component"};

std::string call(GlslCallContext& c) {
    return glsl_function_call(c, "spec_gloss", {c.rgb(0), c.rgb(1), c.scalar(2)});
}

}  // namespace

extern const NodeKind kSpecGlossNode{.name = "spec_gloss",
                                     .role = NodeRole::Closure,
                                     .inputs = kInputs,
                                     .closure = evaluate,
                                     .glsl = kGlsl,
                                     .glsl_dependencies = kGlslDependencies,
                                     .glsl_call = call,
                                     .closure_types = closure_type_bit(ClosureType::Dielectric)};

}  // namespace mvpl::material::nodes
