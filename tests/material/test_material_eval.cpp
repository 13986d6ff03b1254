// A glTF material through its graph (graph_from_gltf, then graph_eval.h, as every CPU caller
// evaluates it): factors, texture channels as glTF assigns them, and the normal-map fallbacks.
// Textures here are 1×1 (or 2×1 with nearest filtering) so the results do not depend on
// filtering details of scene::Texture.
#include <gtest/gtest.h>

#include "engine/material/graph_eval.h"

namespace mvpl::material {
namespace {

struct SurfaceUv {
    Vec2 uv0{0.0f};
    Vec2 uv1{0.0f};
};

SurfacePoint at(const SurfaceUv& uv, const Frame& frame = Frame()) {
    SurfacePoint p;
    p.uv0 = uv.uv0;
    p.uv1 = uv.uv1;
    p.frame = frame;
    return p;
}

ClosureParams resolve_closure(const scene::Material& m, const std::vector<scene::Texture>& t,
                              const SurfaceUv& uv) {
    return evaluate_closure(graph_from_gltf(m), t, at(uv));
}

Rgb resolve_emission(const scene::Material& m, const std::vector<scene::Texture>& t,
                     const SurfaceUv& uv) {
    return evaluate_emission(graph_from_gltf(m), t, at(uv));
}

Vec3 apply_normal_map(const scene::Material& m, const std::vector<scene::Texture>& t,
                      const SurfaceUv& uv, const Frame& frame) {
    return evaluate_normal(graph_from_gltf(m), t, at(uv, frame));
}

scene::Texture constant_texture(const Vec4& texel) {
    scene::Texture t;
    t.width = 1;
    t.height = 1;
    t.texels = {texel};
    return t;
}

scene::TextureRef ref(int index, int texcoord = 0) {
    scene::TextureRef r;
    r.texture = index;
    r.texcoord = texcoord;
    return r;
}

void expect_vec3_near(const Vec3& a, const Vec3& b, float eps) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

TEST(ResolveClosure, FactorOnlyMaterial) {
    scene::Material m;
    m.base_color = Rgb(0.2f, 0.4f, 0.6f);
    m.metallic = 0.25f;
    m.roughness = 0.75f;
    m.specular = 0.5f;
    m.specular_color = Rgb(1.5f, 1.0f, 0.5f);  // > 1 is allowed by KHR_materials_specular
    m.ior = 1.33f;
    const ClosureParams c = resolve_closure(m, {}, SurfaceUv{});
    EXPECT_EQ(c.base_color, m.base_color);
    EXPECT_FLOAT_EQ(c.metallic, 0.25f);
    EXPECT_FLOAT_EQ(c.roughness, 0.75f);
    EXPECT_FLOAT_EQ(c.specular, 0.5f);
    EXPECT_EQ(c.specular_color, m.specular_color);
    EXPECT_FLOAT_EQ(c.ior, 1.33f);
    EXPECT_FALSE(c.is_lambertian());
}

TEST(ResolveClosure, FactorsAreClampedToGltfRanges) {
    scene::Material m;
    m.base_color = Rgb(1.5f, -0.5f, 0.5f);
    m.metallic = 2.0f;
    m.roughness = -1.0f;
    m.specular = 1.5f;
    const ClosureParams c = resolve_closure(m, {}, SurfaceUv{});
    EXPECT_EQ(c.base_color, Rgb(1.0f, 0.0f, 0.5f));
    EXPECT_EQ(c.metallic, 1.0f);
    EXPECT_EQ(c.roughness, 0.0f);
    EXPECT_EQ(c.specular, 1.0f);
}

// The Cornell box's materials: metallic 0 and KHR_materials_specular 0 shade as pure Lambertian.
TEST(ResolveClosure, CornellBoxMaterialsAreLambertian) {
    scene::Material m;
    m.base_color = Rgb(0.885809f, 0.698859f, 0.666422f);
    m.metallic = 0.0f;
    m.roughness = 1.0f;
    m.specular = 0.0f;
    const ClosureParams c = resolve_closure(m, {}, SurfaceUv{});
    EXPECT_TRUE(c.is_lambertian());
    EXPECT_EQ(c.base_color, m.base_color);
    // The glTF defaults (metallic 1) are not Lambertian.
    EXPECT_FALSE(resolve_closure(scene::Material{}, {}, SurfaceUv{}).is_lambertian());
}

TEST(ResolveClosure, TextureChannelsMultiplyFactors) {
    std::vector<scene::Texture> textures = {
        constant_texture(Vec4(0.5f, 0.25f, 1.0f, 0.3f)),  // base colour (alpha ignored)
        constant_texture(Vec4(0.9f, 0.5f, 0.2f, 1.0f)),   // metallic-roughness: G, B
        constant_texture(Vec4(0.1f, 0.1f, 0.1f, 0.4f)),   // specular: A
        constant_texture(Vec4(0.5f, 1.0f, 0.25f, 1.0f)),  // specular colour: RGB
    };
    scene::Material m;
    m.base_color = Rgb(0.8f);
    m.base_color_texture = ref(0);
    m.metallic = 0.5f;
    m.roughness = 0.8f;
    m.metallic_roughness_texture = ref(1);
    m.specular = 0.5f;
    m.specular_texture = ref(2);
    m.specular_color = Rgb(2.0f);
    m.specular_color_texture = ref(3);
    const ClosureParams c = resolve_closure(m, textures, SurfaceUv{Vec2(0.3f, 0.7f), Vec2(0.0f)});
    expect_vec3_near(c.base_color, Rgb(0.4f, 0.2f, 0.8f), 1e-5f);
    EXPECT_NEAR(c.roughness, 0.8f * 0.5f, 1e-5f);
    EXPECT_NEAR(c.metallic, 0.5f * 0.2f, 1e-5f);
    EXPECT_NEAR(c.specular, 0.5f * 0.4f, 1e-5f);
    expect_vec3_near(c.specular_color, Rgb(1.0f, 2.0f, 0.5f), 1e-5f);
}

TEST(ResolveClosure, TexcoordSelectsTheUvSet) {
    scene::Texture two;
    two.width = 2;
    two.height = 1;
    two.texels = {Vec4(0.2f, 0.2f, 0.2f, 1.0f), Vec4(0.6f, 0.6f, 0.6f, 1.0f)};
    two.filter = scene::Filter::Nearest;
    two.wrap_s = two.wrap_t = scene::Wrap::ClampToEdge;
    scene::Material m;
    m.base_color = Rgb(1.0f);
    const SurfaceUv uv{Vec2(0.1f, 0.5f), Vec2(0.9f, 0.5f)};
    m.base_color_texture = ref(0, 0);
    EXPECT_NEAR(resolve_closure(m, {two}, uv).base_color.r, 0.2f, 1e-5f);
    m.base_color_texture = ref(0, 1);
    EXPECT_NEAR(resolve_closure(m, {two}, uv).base_color.r, 0.6f, 1e-5f);
}

TEST(ResolveClosure, MissingTextureIndexIsIgnored) {
    scene::Material m;
    m.base_color = Rgb(0.5f);
    m.base_color_texture = ref(3);  // the scene has no texture 3
    EXPECT_EQ(resolve_closure(m, {}, SurfaceUv{}).base_color, Rgb(0.5f));
}

TEST(ResolveEmission, FactorStrengthAndTexture) {
    scene::Material m;
    m.emissive = Rgb(1.0f, 0.5f, 0.25f);
    m.emissive_strength = 4.0f;
    expect_vec3_near(resolve_emission(m, {}, SurfaceUv{}), Rgb(4.0f, 2.0f, 1.0f), 1e-5f);
    m.emissive_texture = ref(0);
    expect_vec3_near(
        resolve_emission(m, {constant_texture(Vec4(0.5f, 1.0f, 0.0f, 1.0f))}, SurfaceUv{}),
        Rgb(2.0f, 2.0f, 0.0f), 1e-5f);
    EXPECT_EQ(resolve_emission(scene::Material{}, {}, SurfaceUv{}), Rgb(0.0f));
}

TEST(NormalMap, WithoutTextureReturnsTheFrameNormal) {
    const Frame frame(glm::normalize(Vec3(0.3f, -0.2f, 0.9f)));
    EXPECT_EQ(apply_normal_map(scene::Material{}, {}, SurfaceUv{}, frame), frame.n);
}

TEST(NormalMap, FlatTexelKeepsTheNormalAndTiltedTexelRotatesIt) {
    const Frame frame(Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1));
    scene::Material m;
    m.normal_texture = ref(0);
    // (0.5, 0.5, 1) encodes the tangent-space normal (0, 0, 1).
    expect_vec3_near(
        apply_normal_map(m, {constant_texture(Vec4(0.5f, 0.5f, 1.0f, 1.0f))}, SurfaceUv{}, frame),
        Vec3(0, 0, 1), 1e-5f);
    // rgb (0.8, 0.5, 0.9) encodes (0.6, 0, 0.8): tilted towards the tangent.
    const std::vector<scene::Texture> tilted = {constant_texture(Vec4(0.8f, 0.5f, 0.9f, 1.0f))};
    expect_vec3_near(apply_normal_map(m, tilted, SurfaceUv{}, frame), Vec3(0.6f, 0.0f, 0.8f),
                     1e-5f);
    // normal_scale scales x and y before normalising: (1.2, 0, 0.8) / |…|.
    m.normal_scale = 2.0f;
    expect_vec3_near(apply_normal_map(m, tilted, SurfaceUv{}, frame),
                     glm::normalize(Vec3(1.2f, 0.0f, 0.8f)), 1e-5f);
    // Expressed in the given (rotated) tangent frame.
    const Frame rotated(Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(1, 0, 0));
    m.normal_scale = 1.0f;
    expect_vec3_near(apply_normal_map(m, tilted, SurfaceUv{}, rotated), Vec3(0.8f, 0.6f, 0.0f),
                     1e-5f);
}

TEST(NormalMap, DegenerateTexelFallsBackToTheFrameNormal) {
    const Frame frame(glm::normalize(Vec3(0.0f, 0.6f, 0.8f)));
    scene::Material m;
    m.normal_texture = ref(0);
    // (0.5, 0.5, 0.5) decodes to the zero vector.
    const Vec3 n =
        apply_normal_map(m, {constant_texture(Vec4(0.5f, 0.5f, 0.5f, 1.0f))}, SurfaceUv{}, frame);
    expect_vec3_near(n, frame.n, 1e-6f);
}

}  // namespace
}  // namespace mvpl::material
