#pragma once
// Resolves a scene material at a surface point into a closure and its emitted radiance
// (texture lookups with KHR_texture_transform, factors multiplied in).
#include <vector>

#include "engine/material/closure.h"
#include "engine/scene/scene.h"

namespace mvpl::material {

struct SurfaceUv {
    Vec2 uv0{0.0f};
    Vec2 uv1{0.0f};
};

// The closure of the material's factors alone (no texture), as uploaded for the GPU's G-buffer
// until textures are bound there.
ClosureParams factor_closure(const scene::Material& material);
ClosureParams resolve_closure(const scene::Material& material,
                              const std::vector<scene::Texture>& textures, const SurfaceUv& uv);
Rgb resolve_emission(const scene::Material& material, const std::vector<scene::Texture>& textures,
                     const SurfaceUv& uv);

// Shading normal after the material's normal texture (glTF tangent space: RGB mapped to [-1, 1],
// xy scaled by normal_scale). `tangent_frame` is (tangent, bitangent, interpolated normal); the
// result is unit length. Without a normal texture it returns tangent_frame.n.
Vec3 apply_normal_map(const scene::Material& material, const std::vector<scene::Texture>& textures,
                      const SurfaceUv& uv, const Frame& tangent_frame);

}  // namespace mvpl::material
