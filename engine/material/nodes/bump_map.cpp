// bump_map: Blinn (1978) with the height h(u, v) of its input and forward differences over one
// texel (du, dv) of the height's texture: n' = normalize(n − scale · (∂h/∂u · t̂ + ∂h/∂v · b̂)),
// t̂, b̂ the unit tangent and bitangent, scale = Node::value.x (height units per uv unit).
// Approximation: dp/du and dp/dv are taken as unit length (exact for a uv mapping of one metre
// per unit); the scale absorbs the rest.
//
// glTF has no height maps; the Mitsuba loader creates it for Mitsuba's `bumpmap` BSDF, whose
// `scale` has this meaning (scene::Material::bump_texture).
#include "engine/material/node_graph.h"

namespace mvpl::material::nodes {
namespace {

constexpr std::string_view kInputs[] = {"height (scalar)"};

Vec3 evaluate(const NodeContext& c) {
    const SurfacePoint& p = c.point();
    const Vec2 step = c.texel_step(0);
    // The height at (u, v), (u + du, v) and (u, v + dv), both uv sets shifted alike.
    SurfacePoint pu = p;
    pu.uv0.x += step.x;
    pu.uv1.x += step.x;
    SurfacePoint pv = p;
    pv.uv0.y += step.y;
    pv.uv1.y += step.y;
    const float h = c.input_at(0, p).x;
    const float dh_du = step.x > 0.0f ? (c.input_at(0, pu).x - h) / step.x : 0.0f;
    const float dh_dv = step.y > 0.0f ? (c.input_at(0, pv).x - h) / step.y : 0.0f;
    const Frame& f = p.frame;
    const Vec3 n = f.n - c.node().value.x * (dh_du * f.s + dh_dv * f.t);
    const float len2 = glm::dot(n, n);
    if (!(len2 > 1e-12f) || !std::isfinite(len2)) return f.n;
    return n / std::sqrt(len2);
}

constexpr std::string_view kGlsl =
    R"(vec3 bump_map(float h, float h_u, float h_v, float du, float dv, float scale, SurfacePoint s) {
    const float dh_du = du > 0.0 ? (h_u - h) / du : 0.0;
    const float dh_dv = dv > 0.0 ? (h_v - h) / dv : 0.0;
    const vec3 n = s.n - scale * (dh_du * s.t + dh_dv * s.b);
    const float len2 = dot(n, n);
    if (!(len2 > 1e-12) || isinf(len2)) return s.n;
    return n / sqrt(len2);
}
// The surface point with both uv sets moved by d.
SurfacePoint bump_shift(SurfacePoint s, vec2 d) {
    s.uv0 += d;
    s.uv1 += d;
    return s;
}
)";
constexpr std::string_view kGlslDependencies[] = {"SurfacePoint"};

std::string call(GlslCallContext& c) {
    c.require("bump_map");
    const Vec2 step = c.texel_step(0);
    const std::string h = c.scalar_function(0);
    const std::string du = glsl_number(step.x);
    const std::string dv = glsl_number(step.y);
    return "bump_map(" + h + "(s), " + h + "(bump_shift(s, vec2(" + du + ", 0.0))), " + h +
           "(bump_shift(s, vec2(0.0, " + dv + "))), " + du + ", " + dv + ", " +
           glsl_number(c.node().value.x) + ", s)";
}

}  // namespace

extern const NodeKind kBumpMapNode{.name = "bump_map",
                                   .role = NodeRole::Normal,
                                   .inputs = kInputs,
                                   .normal = evaluate,
                                   .glsl = kGlsl,
                                   .glsl_dependencies = kGlslDependencies,
                                   .glsl_call = call};

}  // namespace mvpl::material::nodes
