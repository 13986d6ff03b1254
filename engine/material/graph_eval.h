#pragma once
// CPU evaluation of a material graph at a surface point: the closure, the emitted radiance and
// the shading normal, with the node evaluators of node_eval.h. The GPU twin is the per-material
// function that material_codegen.h generates.
#include <vector>

#include "engine/material/node_eval.h"
#include "engine/material/node_graph.h"

namespace mvpl::material {

// The value of one node input (a vec4, or one channel broadcast to all four).
Vec4 evaluate_input(const MaterialGraph& graph, const NodeInput& input,
                    const std::vector<scene::Texture>& textures, const SurfacePoint& p);

ClosureParams evaluate_closure(const MaterialGraph& graph,
                               const std::vector<scene::Texture>& textures, const SurfacePoint& p);
Rgb evaluate_emission(const MaterialGraph& graph, const std::vector<scene::Texture>& textures,
                      const SurfacePoint& p);
// p.frame.n when the graph has no normal node.
Vec3 evaluate_normal(const MaterialGraph& graph, const std::vector<scene::Texture>& textures,
                     const SurfacePoint& p);

// The uv step of the bump map's finite differences for a height input: one texel of the first
// texture it reads (1/1024 when it reads none).
Vec2 bump_step(const MaterialGraph& graph, const NodeInput& height,
               const std::vector<scene::Texture>& textures);

}  // namespace mvpl::material
