#pragma once
// The C++ evaluator of each node kind of node_graph.h, one function per kind, named as its GLSL
// twin in glsl_library.cpp (tests/gpu/test_node_eval.cpp runs both on the same inputs).
#include "engine/core/color.h"
#include "engine/core/math.h"
#include "engine/material/closure.h"
#include "engine/scene/texture.h"

namespace mvpl::material {

// What value and normal nodes read of the surface point.
struct SurfacePoint {
    Vec2 uv0{0.0f};
    Vec2 uv1{0.0f};
    Vec4 color{1.0f};  // COLOR_0, white where the mesh has none
    // (tangent, bitangent, interpolated shading normal); the tangent and bitangent are the
    // directions of increasing u and v (dp/du, dp/dv normalised).
    Frame frame;
};

// image_texture: factor · texel at the transformed coordinate (KHR_texture_transform, then the
// sampler's wrap and filter: scene::Texture::sample).
inline Vec4 image_texture(const scene::Texture& texture, const scene::TextureRef& ref,
                          const Vec4& factor, const Vec2& uv) {
    return factor * texture.sample(ref.transform(uv));
}

inline Vec4 vertex_color(const Vec4& factor, const Vec4& color) {
    return factor * color;
}

// mix: a + (b − a) · t, t clamped to [0, 1] (a factor outside that range would extrapolate).
inline Vec4 mix_node(const Vec4& a, const Vec4& b, float t) {
    const float f = std::clamp(t, 0.0f, 1.0f);
    return a + (b - a) * f;
}

inline Vec4 emission(const Vec4& colour, float strength) {
    return Vec4(Vec3(colour) * strength, 1.0f);
}

// glTF 2.0 §3.9.3: normalize((texel · 2 − 1) · (scale, scale, 1)) in the tangent frame; a
// degenerate result keeps the interpolated normal.
Vec3 normal_map(const Vec3& texel, float scale, const Frame& frame);

// Bump mapping (Blinn 1978) with the height h(u, v) and its forward differences over one step
// (du, dv) in uv: n' = normalize(n − scale · (∂h/∂u · t̂ + ∂h/∂v · b̂)), where t̂, b̂ are the
// unit tangent and bitangent. Approximation: the surface's dp/du, dp/dv are taken as unit length
// (exact for a uv mapping of one metre per unit); the scale absorbs the rest.
Vec3 bump_map(float h, float h_u, float h_v, float du, float dv, float scale, const Frame& frame);

// Closure nodes: the ClosureParams each resolves to (clamped to the glTF ranges, as Bsdf does).
ClosureParams lambertian(const Rgb& base_color);
ClosureParams ggx_conductor(const Rgb& f0, float roughness);
ClosureParams dielectric_diffuse(const Rgb& base_color, float roughness, float specular,
                                 const Rgb& specular_color, float ior);
ClosureParams metal_rough(const Rgb& base_color, float metallic, float roughness, float specular,
                          const Rgb& specular_color, float ior);
// The reflection lobe of a rough dielectric interface: dielectric_diffuse over a black base
// (the transmitted lobe is not modelled, see graph_from_gltf).
ClosureParams rough_dielectric(float roughness, float specular, const Rgb& specular_color,
                               float ior);

// Closure types the shading code distinguishes, narrowest first. closure_type() of a closure is
// the narrowest type whose evaluator gives exactly Bsdf::eval.
enum class ClosureType : uint32_t { Lambertian = 0, Conductor = 1, Dielectric = 2, MetalRough = 3 };
inline constexpr int kClosureTypeCount = 4;
ClosureType closure_type(const ClosureParams& params);

}  // namespace mvpl::material
