// normal_map: glTF 2.0 §3.9.3, normalize((texel · 2 − 1) · (scale, scale, 1)) in the tangent
// frame, scale = Node::value.x (normalTexture.scale); a degenerate result (a zero texel or a
// degenerate tangent frame has no direction) keeps the interpolated normal rather than NaN.
#include "engine/material/node_graph.h"

namespace mvpl::material::nodes {
namespace {

constexpr std::string_view kInputs[] = {"texel (rgb)"};

Vec3 evaluate(const NodeContext& c) {
    const Frame& frame = c.point().frame;
    const float scale = c.node().value.x;
    Vec3 n_ts = 2.0f * Vec3(c.input(0)) - Vec3(1.0f);
    n_ts.x *= scale;
    n_ts.y *= scale;
    const Vec3 n = frame.to_world(n_ts);
    const float len2 = glm::dot(n, n);
    if (!(len2 > 1e-12f) || !std::isfinite(len2)) return frame.n;
    const Vec3 result = n / std::sqrt(len2);
    return is_finite(result) ? result : frame.n;
}

constexpr std::string_view kGlsl = R"(vec3 normal_map(vec3 texel, float scale, SurfacePoint s) {
    vec3 n_ts = 2.0 * texel - vec3(1.0);
    n_ts.xy *= scale;
    const vec3 n = s.t * n_ts.x + s.b * n_ts.y + s.n * n_ts.z;
    const float len2 = dot(n, n);
    if (!(len2 > 1e-12) || isinf(len2)) return s.n;
    return n / sqrt(len2);
}
)";
constexpr std::string_view kGlslDependencies[] = {"SurfacePoint"};

std::string call(GlslCallContext& c) {
    return glsl_function_call(c, "normal_map", {c.rgb(0), glsl_number(c.node().value.x), "s"});
}

}  // namespace

extern const NodeKind kNormalMapNode{.name = "normal_map",
                                     .role = NodeRole::Normal,
                                     .inputs = kInputs,
                                     .normal = evaluate,
                                     .glsl = kGlsl,
                                     .glsl_dependencies = kGlslDependencies,
                                     .glsl_call = call};

}  // namespace mvpl::material::nodes
