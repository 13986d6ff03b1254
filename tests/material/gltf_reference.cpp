// The glTF 2.0 metallic-roughness material read straight from the specification (§3.9.2,
// §3.9.3, KHR_materials_specular), without the node graph: the independent computation that
// test_material_graph.cpp holds the graph's CPU evaluation to. (It was the engine's own CPU path
// until every caller evaluated the graphs; transmission is not part of it.)
#include "tests/material/gltf_reference.h"

#include <optional>

namespace mvpl::material::testing {

namespace {

// The texel that `ref` addresses at this surface point, or nullopt when the material has no such
// texture (or names one that the scene does not hold). SurfaceUv carries TEXCOORD_0 and _1 only;
// any other set falls back to TEXCOORD_0.
std::optional<Vec4> lookup(const scene::TextureRef& ref,
                           const std::vector<scene::Texture>& textures, const SurfaceUv& uv) {
    if (!ref.valid() || static_cast<size_t>(ref.texture) >= textures.size()) return std::nullopt;
    const Vec2& coords = ref.texcoord == 1 ? uv.uv1 : uv.uv0;
    return textures[static_cast<size_t>(ref.texture)].sample(ref.transform(coords));
}

}  // namespace

ClosureParams factor_closure(const scene::Material& material) {
    ClosureParams c;
    c.base_color = material.base_color;
    c.metallic = material.metallic;
    c.roughness = material.roughness;
    c.specular = material.specular;
    c.specular_color = material.specular_color;
    c.ior = material.ior;
    return c;
}

ClosureParams resolve_closure(const scene::Material& material,
                              const std::vector<scene::Texture>& textures, const SurfaceUv& uv) {
    ClosureParams c = factor_closure(material);
    // glTF 2.0 §3.9.2: factors multiply the linear texture values; the base colour texture's
    // alpha is coverage, not a BRDF parameter.
    if (const auto t = lookup(material.base_color_texture, textures, uv)) c.base_color *= Rgb(*t);
    // metallicRoughnessTexture: roughness in G, metallic in B.
    if (const auto t = lookup(material.metallic_roughness_texture, textures, uv)) {
        c.roughness *= t->g;
        c.metallic *= t->b;
    }
    // KHR_materials_specular: strength in A, colour in RGB.
    if (const auto t = lookup(material.specular_texture, textures, uv)) c.specular *= t->a;
    if (const auto t = lookup(material.specular_color_texture, textures, uv)) {
        c.specular_color *= Rgb(*t);
    }
    return clamp_to_valid_ranges(c);
}

Rgb resolve_emission(const scene::Material& material, const std::vector<scene::Texture>& textures,
                     const SurfaceUv& uv) {
    Rgb e = material.emission();
    if (const auto t = lookup(material.emissive_texture, textures, uv)) e *= Rgb(*t);
    return e;
}

Vec3 apply_normal_map(const scene::Material& material, const std::vector<scene::Texture>& textures,
                      const SurfaceUv& uv, const Frame& tangent_frame) {
    const std::optional<Vec4> t = lookup(material.normal_texture, textures, uv);
    if (!t) return tangent_frame.n;
    // glTF 2.0 §3.9.3: normal = normalize((texel · 2 − 1) · (scale, scale, 1)) in tangent space.
    Vec3 n_ts = 2.0f * Vec3(*t) - Vec3(1.0f);
    n_ts.x *= material.normal_scale;
    n_ts.y *= material.normal_scale;
    const Vec3 n = tangent_frame.to_world(n_ts);
    const float len2 = glm::dot(n, n);
    // A zero texel (or a degenerate tangent frame) has no direction: keep the geometric shading
    // normal rather than returning NaN.
    if (!(len2 > 1e-12f) || !std::isfinite(len2)) return tangent_frame.n;
    const Vec3 result = n / std::sqrt(len2);
    return is_finite(result) ? result : tangent_frame.n;
}

}  // namespace mvpl::material::testing
