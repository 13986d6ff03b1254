#pragma once
// A material node kind in one place (docs/design.md, "Shader chain"): its name, its inputs, its C++
// evaluator, its GLSL function with the functions that one depends on, and how a material's
// generated code calls it. Each kind is one file under nodes/ that defines its NodeKind, and one
// line in node_registry.cpp that registers it by name — Mitsuba's one plugin a file, nori's
// registration — so that the CPU evaluator (graph_eval.h) and the GLSL generator
// (material_codegen.h) know no kind by name.
#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>

#include "engine/core/color.h"
#include "engine/core/math.h"
#include "engine/material/closure.h"
#include "engine/material/glsl_literals.h"
#include "engine/scene/texture.h"

namespace mvpl::material {

struct Node;

// What value and normal nodes read of the surface point.
struct SurfacePoint {
    Vec2 uv0{0.0f};
    Vec2 uv1{0.0f};
    Vec4 color{1.0f};  // COLOR_0, white where the mesh has none
    // (tangent, bitangent, interpolated shading normal); the tangent and bitangent are the
    // directions of increasing u and v (dp/du, dp/dv normalised).
    Frame frame;
};

// What a node's C++ evaluator reads: its own parameters, the surface point, and its inputs
// evaluated by the graph (graph_eval.cpp), at this point or at another one (bump mapping).
class NodeContext {
public:
    virtual ~NodeContext() = default;
    virtual const Node& node() const = 0;
    virtual const SurfacePoint& point() const = 0;
    // Input k's value at p (a vec4, or one channel broadcast to all four); zero when unconnected.
    virtual Vec4 input_at(int k, const SurfacePoint& p) const = 0;
    // The uv size of one texel of the first texture that input k reads (1/1024 when none).
    virtual Vec2 texel_step(int k) const = 0;
    // The texture the node's own reference names, or nullptr when the scene has no such texture.
    virtual const scene::Texture* texture() const = 0;

    Vec4 input(int k) const { return input_at(k, point()); }
    float scalar(int k) const { return input(k).x; }
    Rgb rgb(int k) const { return Rgb(Vec3(input(k))); }
};

// What a node's GLSL call generator writes with (material_codegen.cpp): its inputs as GLSL
// expressions, texture bindings, and the functions it needs. Generated material code names the
// surface point `s` (a SurfacePoint) wherever a node expression is evaluated.
class GlslCallContext {
public:
    virtual ~GlslCallContext() = default;
    virtual const Node& node() const = 0;
    virtual std::string input(int k) = 0;   // vec4 expression
    virtual std::string scalar(int k) = 0;  // float expression (constants as plain literals)
    virtual std::string rgb(int k) = 0;     // vec3 expression
    // The name of a generated `float f(SurfacePoint s)` that returns input k's x at s.
    virtual std::string scalar_function(int k) = 0;
    virtual Vec2 texel_step(int k) const = 0;
    // The texture of the node's own reference, or nullptr when the scene has no such texture.
    virtual const scene::Texture* texture() const = 0;
    // The sampler2D the node's texture is bound to; empty when textures are not bound.
    virtual std::string sampler() = 0;
    virtual void require(std::string_view function) = 0;
};

// `name(args…)`, with the function `name` required: how most kinds call their GLSL function.
std::string glsl_function_call(GlslCallContext& c, std::string_view name,
                               std::initializer_list<std::string> args);

// Which of a material's three outputs a node kind can drive.
enum class NodeRole { Value, Normal, Closure };

struct NodeKind {
    std::string_view name{};  // the registry's key and the GLSL function's name
    NodeRole role = NodeRole::Value;
    // Input slots in order (Node::inputs); a slot's name says what it is read as.
    std::span<const std::string_view> inputs{};
    // The C++ evaluator of the role: value (Value), normal (Normal) or closure (Closure).
    Vec4 (*value)(const NodeContext&) = nullptr;
    Vec3 (*normal)(const NodeContext&) = nullptr;
    ClosureParams (*closure)(const NodeContext&) = nullptr;
    // The GLSL function(s) named `name` (may be empty: constants are literals) and what they
    // need, emitted once each by GlslModule.
    std::string_view glsl{};
    std::span<const std::string_view> glsl_dependencies{};
    // The GLSL expression of the node's output (vec4, vec3 normal or Closure).
    std::string (*glsl_call)(GlslCallContext&) = nullptr;
    // Closure nodes: the ClosureTypes it can produce at run time (bit i: ClosureType i), e.g.
    // a dielectric-diffuse node whose specular input is 0 somewhere is Lambertian there.
    uint32_t closure_types = 0;
};

// The registered kinds, in registration order.
std::span<const NodeKind* const> node_kinds();
// nullptr when no kind has that name.
const NodeKind* find_node_kind(std::string_view name);
// Throws std::logic_error for an unknown name (a bug in a loader, not an input error).
const NodeKind& node_kind(std::string_view name);

}  // namespace mvpl::material
