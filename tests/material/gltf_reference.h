#pragma once
// A glTF material resolved directly from the specification's formulas (no node graph): the
// reference for the graph's CPU evaluation in test_material_graph.cpp.
#include <vector>

#include "engine/material/closure.h"
#include "engine/scene/scene.h"

namespace mvpl::material::testing {

struct SurfaceUv {
    Vec2 uv0{0.0f};
    Vec2 uv1{0.0f};
};

ClosureParams factor_closure(const scene::Material& material);
ClosureParams resolve_closure(const scene::Material& material,
                              const std::vector<scene::Texture>& textures, const SurfaceUv& uv);
Rgb resolve_emission(const scene::Material& material, const std::vector<scene::Texture>& textures,
                     const SurfaceUv& uv);
// `tangent_frame` is (tangent, bitangent, interpolated normal); without a normal texture the
// result is tangent_frame.n.
Vec3 apply_normal_map(const scene::Material& material, const std::vector<scene::Texture>& textures,
                      const SurfaceUv& uv, const Frame& tangent_frame);

}  // namespace mvpl::material::testing
