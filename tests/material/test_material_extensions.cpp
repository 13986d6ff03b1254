// KHR_materials_pbrSpecularGlossiness and KHR_materials_unlit through their graphs
// (graph_from_gltf, then graph_eval.h, as every CPU caller evaluates them), against the
// extensions' own formulas. tests/gpu/test_material_extensions.cpp holds the GPU to the same.
#include <gtest/gtest.h>

#include "engine/material/bsdf.h"
#include "engine/material/graph_eval.h"

namespace mvpl::material {
namespace {

scene::Texture constant_texture(const Vec4& texel) {
    scene::Texture t;
    t.width = 1;
    t.height = 1;
    t.texels = {texel};
    return t;
}

scene::TextureRef ref(int index) {
    scene::TextureRef r;
    r.texture = index;
    return r;
}

void expect_rgb_near(const Rgb& a, const Rgb& b, float eps) {
    EXPECT_NEAR(a.r, b.r, eps);
    EXPECT_NEAR(a.g, b.g, eps);
    EXPECT_NEAR(a.b, b.b, eps);
}

// The extension's BRDF inputs: c_diff = diffuse · (1 − max(specular)), F0 = specular,
// α = (1 − glossiness)², each channel the factor times the texture; F90 = 1 (glTF's Schlick).
TEST(SpecGloss, ClosureHoldsTheExtensionsBrdfInputs) {
    const std::vector<scene::Texture> textures = {
        constant_texture(Vec4(0.5f, 0.8f, 1.0f, 0.6f)),  // diffuse RGB, A coverage
        constant_texture(Vec4(0.2f, 0.5f, 0.1f, 0.5f)),  // specular RGB, glossiness A
    };
    scene::Material m;
    m.shading = scene::ShadingModel::SpecGloss;
    m.base_color = Rgb(0.8f, 0.5f, 1.0f);
    m.base_color_texture = ref(0);
    m.spec_gloss_specular = Rgb(1.0f, 0.6f, 0.5f);
    m.glossiness = 0.8f;
    m.specular_glossiness_texture = ref(1);
    const MaterialGraph g = graph_from_gltf(m);
    EXPECT_EQ(g.nodes[size_t(g.closure)].kind, &node_kind("spec_gloss"));
    const ClosureParams c = evaluate_closure(g, textures, SurfacePoint{});
    const Rgb specular(0.2f, 0.3f, 0.05f);
    const float glossiness = 0.4f;
    expect_rgb_near(c.base_color, Rgb(0.4f, 0.4f, 1.0f) * (1.0f - 0.3f), 1e-5f);
    EXPECT_NEAR(c.roughness, 1.0f - glossiness, 1e-6f);
    EXPECT_EQ(c.metallic, 0.0f);
    // The closure's dielectric layer has exactly the extension's Fresnel.
    const DielectricLayer layer = dielectric_layer(c.specular_color, c.specular, c.ior);
    expect_rgb_near(layer.f0, specular, 1e-6f);
    EXPECT_EQ(layer.f90, 1.0f);
    EXPECT_EQ(closure_type(c), ClosureType::Dielectric);
}

// At the mirror configuration of a smooth surface the BSDF's specular lobe is F(wo·h) · D · G /
// (4 cos cos) with F0 = specular; its diffuse lobe is c_diff's (no reflection is lost).
TEST(SpecGloss, BsdfReflectsTheSpecularColourAtNormalIncidence) {
    scene::Material m;
    m.shading = scene::ShadingModel::SpecGloss;
    m.base_color = Rgb(0.0f);  // a metal: diffuse black
    m.spec_gloss_specular = Rgb(1.0f, 0.766f, 0.336f);
    m.glossiness = 1.0f;
    const ClosureParams c = evaluate_closure(graph_from_gltf(m), {}, SurfacePoint{});
    const Bsdf bsdf(c);
    const Vec3 n(0.0f, 0.0f, 1.0f);
    // A cosine-weighted albedo check would be the conductor's; at normal incidence the sampled
    // mirror direction carries the F0 colour as its weight (G ≈ 1 for the narrowest lobe).
    const std::optional<BsdfSample> s = bsdf.sample(n, Vec2(0.5f, 0.5f), 0.0f);
    ASSERT_TRUE(s.has_value());
    expect_rgb_near(s->weight, m.spec_gloss_specular, 2e-3f);
    expect_rgb_near(bsdf.eval_diffuse(n, n), Rgb(0.0f), 1e-7f);
}

TEST(SpecGloss, MetalRoughExtensionsDoNotApply) {
    scene::Material m;
    m.shading = scene::ShadingModel::SpecGloss;
    m.transmission = 1.0f;  // KHR_materials_specular and _transmission exclude spec-gloss
    m.specular = 0.0f;
    const MaterialGraph g = graph_from_gltf(m);
    EXPECT_LT(g.transmission.node, 0);
    EXPECT_EQ(g.nodes[size_t(g.closure)].kind, &node_kind("spec_gloss"));
}

// colour = baseColorFactor · baseColorTexture · COLOR_0, emitted; nothing reflected; the
// emissive, normal and metal-rough properties ignored.
TEST(Unlit, EmitsTheBaseColourAndReflectsNothing) {
    const std::vector<scene::Texture> textures = {constant_texture(Vec4(0.5f, 1.0f, 0.25f, 1.0f))};
    scene::Material m;
    m.shading = scene::ShadingModel::Unlit;
    m.base_color = Rgb(1.0f, 0.2176f, 0.5f);
    m.base_color_texture = ref(0);
    m.emissive = Rgb(3.0f);
    m.normal_texture = ref(0);
    m.metallic = 0.0f;
    const MaterialGraph g = graph_from_gltf(m, {.vertex_colors = true});
    SurfacePoint p;
    p.color = Vec4(0.5f, 1.0f, 1.0f, 1.0f);
    expect_rgb_near(evaluate_emission(g, textures, p), Rgb(0.25f, 0.2176f, 0.125f), 1e-6f);
    const ClosureParams c = evaluate_closure(g, textures, p);
    expect_rgb_near(c.base_color, Rgb(0.0f), 0.0f);
    EXPECT_TRUE(c.is_lambertian());
    EXPECT_LT(g.normal, 0);
    const Vec3 n(0.0f, 0.0f, 1.0f);
    expect_rgb_near(Bsdf(c).eval(n, glm::normalize(Vec3(0.3f, 0.1f, 1.0f))), Rgb(0.0f), 0.0f);
}

TEST(Unlit, BlackBaseColourIsNoEmitter) {
    scene::Material m;
    m.shading = scene::ShadingModel::Unlit;
    m.base_color = Rgb(0.0f);
    EXPECT_LT(graph_from_gltf(m).emission, 0);
    EXPECT_FALSE(m.is_emissive());
    m.base_color = Rgb(0.0f, 0.1f, 0.0f);
    EXPECT_GE(graph_from_gltf(m).emission, 0);
    EXPECT_TRUE(m.is_emissive());
}

}  // namespace
}  // namespace mvpl::material
