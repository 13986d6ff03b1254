#pragma once
// The material node graph (DESIGN.md, "Shader chain"): every material is a small DAG of typed
// nodes. Value nodes (constant, image texture, vertex colour, mix, emission) produce a vec4;
// normal nodes (normal map, bump map) produce the shading normal; closure nodes (Lambertian, GGX
// conductor, dielectric over diffuse, glTF metal-rough, rough dielectric) produce the
// ClosureParams that Bsdf, the VPLs and the G-buffer carry. Each node kind has one C++ evaluator
// (node_eval.h) and one GLSL generator (glsl_library.h, material_codegen.h).
#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "engine/core/math.h"
#include "engine/scene/scene.h"

namespace mvpl::material {

enum class NodeKind : uint8_t {
    Constant,
    ImageTexture,
    VertexColor,
    Mix,
    Emission,
    NormalMap,
    BumpMap,
    Lambertian,
    GgxConductor,
    DielectricDiffuse,
    MetalRough,
    RoughDielectric,
};
inline constexpr int kNodeKindCount = 12;

// The node's name as the generated GLSL calls it (one function per node kind).
std::string_view node_name(NodeKind kind);
bool is_closure_node(NodeKind kind);

// Which part of an input's vec4 a node reads: all four, or one component.
inline constexpr int kAllChannels = -1;

struct NodeInput {
    int node = -1;  // index into MaterialGraph::nodes; -1: unused
    int channel = kAllChannels;
};

// Inputs per kind (unused slots stay -1):
//   Mix:               a, b, factor (scalar)
//   Emission:          colour (rgb); value.x = strength
//   NormalMap:         texel (rgb); value.x = scale (glTF normalTexture.scale)
//   BumpMap:           height (scalar); value.x = scale (height units per uv unit)
//   Lambertian:        base colour
//   GgxConductor:      f0 (rgb), roughness
//   DielectricDiffuse: base colour, roughness, specular, specular colour, ior
//   MetalRough:        base colour, metallic, roughness, specular, specular colour, ior
//   RoughDielectric:   roughness, specular, specular colour, ior
// Constant: value. ImageTexture: texture (the reference, KHR_texture_transform included) and
// value = the factor multiplied into the texel (glTF factors). VertexColor: value multiplied in.
struct Node {
    NodeKind kind = NodeKind::Constant;
    Vec4 value{1.0f};
    scene::TextureRef texture;
    std::array<NodeInput, 6> inputs{};
};

struct MaterialGraph {
    std::vector<Node> nodes;
    int closure = -1;   // a closure node; -1 never happens for graphs of graph_from_gltf
    int emission = -1;  // an Emission node or -1 (not emissive)
    int normal = -1;    // a NormalMap or BumpMap node, or -1 (the interpolated normal)
    bool double_sided = false;

    int add(const Node& node) {
        nodes.push_back(node);
        return int(nodes.size()) - 1;
    }
    // The kinds that occur, including those only reachable from the outputs.
    std::array<bool, kNodeKindCount> kinds() const;
};

// A glTF metallic-roughness material as a graph. The closure node is the narrowest that
// represents the material exactly: constant metallic 0 and specular 0 → Lambertian, constant
// metallic 1 → GGX conductor, constant metallic 0 → dielectric over diffuse (or rough dielectric
// for KHR_materials_transmission = 1), otherwise the metal-rough mix.
//
// KHR_materials_transmission: the transmitted lobe is not modelled (no refraction in the VPL
// renderer nor in the path tracer): a transmission factor t scales the diffuse base by (1 − t),
// so the surface keeps its reflection lobe and the transmitted energy is lost. A fully
// transmissive material becomes the rough dielectric's reflection lobe.
MaterialGraph graph_from_gltf(const scene::Material& material);

}  // namespace mvpl::material
