#pragma once
// The material node graph (docs/design.md, "Shader chain"): every material is a small DAG of nodes
// of the kinds that node_kind.h registers. Value nodes (constant, image texture, vertex colour,
// mix, emission) produce a vec4; normal nodes (normal map, bump map) produce the shading normal;
// closure nodes (Lambertian, GGX conductor, dielectric over diffuse, glTF metal-rough, rough
// dielectric) produce the ClosureParams that Bsdf, the VPLs and the G-buffer carry. The CPU
// (graph_eval.h) and the GPU (material_codegen.h) evaluate the same graphs.
#include <array>
#include <vector>

#include "engine/core/math.h"
#include "engine/material/node_kind.h"
#include "engine/scene/scene.h"

namespace mvpl::material {

// Which part of an input's vec4 a node reads: all four, or one component.
inline constexpr int kAllChannels = -1;

struct NodeInput {
    int node = -1;  // index into MaterialGraph::nodes; -1: unused
    int channel = kAllChannels;
};

// A node's inputs are the slots its kind names (NodeKind::inputs); unused slots stay -1.
// Constant: value. ImageTexture: texture (the reference, KHR_texture_transform included) and
// value = the factor multiplied into the texel (glTF factors). VertexColor: value multiplied in.
// Emission, NormalMap, BumpMap: value.x is the strength or scale.
struct Node {
    const NodeKind* kind = nullptr;  // always set: MaterialGraph::add refuses a node without
    Vec4 value{1.0f};
    scene::TextureRef texture;
    std::array<NodeInput, 6> inputs{};
};

struct MaterialGraph {
    std::vector<Node> nodes;
    int closure = -1;   // a closure node; -1 never happens for graphs of graph_from_gltf
    int emission = -1;  // an Emission node or -1 (not emissive)
    int normal = -1;    // a normal node (NormalMap, BumpMap) or -1: the interpolated normal
    // KHR_materials_transmission on the CPU (ClosureParams::transmission): a value whose rgb is
    // t · base colour, node −1 when opaque. Not an output the GLSL is generated from (kinds()
    // leaves it out): the GPU shades the reflection only.
    NodeInput transmission;
    bool thin_walled = true;  // KHR_materials_volume's thickness is 0
    bool double_sided = false;
    // glTF alpha: the base colour's alpha (factor · texture A · COLOR_0 A) where alpha_mode is
    // not Opaque; unused (node −1) otherwise. Mask cuts the surface where alpha < alpha_cutoff;
    // Blend keeps a hit with probability alpha (hashed transparency: alpha_kept).
    NodeInput alpha;
    scene::AlphaMode alpha_mode = scene::AlphaMode::Opaque;
    float alpha_cutoff = scene::kDefaultAlphaCutoff;
    bool masked() const { return alpha_mode == scene::AlphaMode::Mask && alpha.node >= 0; }
    bool blended() const { return alpha_mode == scene::AlphaMode::Blend && alpha.node >= 0; }
    // Hits on the surface are tested against its alpha (every ray, the G-buffer, shadow maps).
    bool alpha_tested() const { return masked() || blended(); }

    // Throws std::logic_error for a node without a kind.
    int add(const Node& node);
    // The distinct kinds reachable from the outputs, in registration order.
    std::vector<const NodeKind*> kinds() const;
};

// What graph_from_gltf needs to know of the meshes that use a material.
struct GltfGraphOptions {
    // A mesh with COLOR_0 uses the material: the base colour is multiplied by it (a multiply and
    // a vertex_color node), which graphs of other materials leave out.
    bool vertex_colors = false;
};

// A glTF material as a graph. KHR_materials_pbrSpecularGlossiness: the spec_gloss closure node
// (nodes/spec_gloss.cpp gives the exact mapping onto the dielectric-over-diffuse closure).
//
// KHR_materials_unlit ("a constantly shaded surface that is independent of lighting", colour =
// base colour · texture · COLOR_0): a black Lambertian closure (it reflects nothing) with an
// emission node of that colour, so an unlit surface is an area light of radiance base colour in
// every renderer. Why an emitter rather than Blender's camera-rays-only trick: it is the one
// reading in which the surface shows the same radiance to every ray — the camera, a mirror, and
// the surfaces it faces — so the path tracer, the light tracer, the VPLs and the oracle need no
// camera-ray special case and agree by construction; its light onto the scene is what its baked
// shading already claims it sends.
//
// Metallic-roughness: the closure node is the narrowest that
// represents the material exactly: constant metallic 0 and specular 0 → Lambertian, constant
// metallic 1 → GGX conductor, constant metallic 0 → dielectric over diffuse (or rough dielectric
// for KHR_materials_transmission = 1), otherwise the metal-rough mix.
//
// KHR_materials_transmission: a transmission factor t scales the diffuse base by (1 − t) in the
// closure node (what the GPU shades: the reflection), and the graph's `transmission` output is
// t · base colour, the specular BTDF's tint and weight that the CPU's Bsdf adds (the path tracer,
// the light tracer, the specular chains). A fully transmissive material's closure node is the
// rough dielectric's reflection lobe.
MaterialGraph graph_from_gltf(const scene::Material& material,
                              const GltfGraphOptions& options = {});

}  // namespace mvpl::material
