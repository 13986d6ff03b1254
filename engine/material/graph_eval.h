#pragma once
// CPU evaluation of a material graph at a surface point: the closure, the emitted radiance and
// the shading normal, each node by its kind's C++ evaluator (node_kind.h). The GPU twin is the
// per-material function that material_codegen.h generates from the same graph.
#include <vector>

#include "engine/material/node_graph.h"

namespace mvpl::material {

// The value of one node input (a vec4, or one channel broadcast to all four); zero when unused
// or when the input is not a value node.
Vec4 evaluate_input(const MaterialGraph& graph, const NodeInput& input,
                    const std::vector<scene::Texture>& textures, const SurfacePoint& p);

// Black Lambertian when the graph has no closure node.
ClosureParams evaluate_closure(const MaterialGraph& graph,
                               const std::vector<scene::Texture>& textures, const SurfacePoint& p);
Rgb evaluate_emission(const MaterialGraph& graph, const std::vector<scene::Texture>& textures,
                      const SurfacePoint& p);
// p.frame.n when the graph has no normal node.
Vec3 evaluate_normal(const MaterialGraph& graph, const std::vector<scene::Texture>& textures,
                     const SurfacePoint& p);

// The uv step of a bump map's finite differences for a height input: one texel of the first
// texture it reads (1/1024 when it reads none).
Vec2 bump_step(const MaterialGraph& graph, const NodeInput& height,
               const std::vector<scene::Texture>& textures);

}  // namespace mvpl::material
