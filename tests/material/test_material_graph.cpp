// The material graph of a glTF material evaluates to what the glTF specification's formulas give
// (gltf_reference.h, an implementation without the graph), node kinds are the narrowest that
// represent the material, and the GLSL module emits each function once, dependencies first.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "engine/material/bsdf.h"
#include "engine/material/graph_eval.h"
#include "engine/material/material_codegen.h"
#include "tests/material/gltf_reference.h"

namespace mvpl::material {
namespace {

using testing::apply_normal_map;
using testing::resolve_closure;
using testing::resolve_emission;
using testing::SurfaceUv;

scene::Texture random_texture(std::mt19937& rng) {
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    scene::Texture t;
    t.width = 1 + int(rng() % 5);
    t.height = 1 + int(rng() % 5);
    for (int i = 0; i < t.width * t.height; ++i)
        t.texels.emplace_back(u(rng), u(rng), u(rng), u(rng));
    t.wrap_s = scene::Wrap(rng() % 3);
    t.wrap_t = scene::Wrap(rng() % 3);
    t.filter = scene::Filter(rng() % 2);
    return t;
}

scene::TextureRef random_ref(std::mt19937& rng, int textures) {
    std::uniform_real_distribution<float> u(-2.0f, 2.0f);
    scene::TextureRef r;
    if (rng() % 2 == 0) return r;  // no texture in this slot
    r.texture = int(rng() % uint32_t(textures));
    r.texcoord = int(rng() % 2);
    r.offset = Vec2(u(rng), u(rng));
    r.rotation = rng() % 2 ? u(rng) : 0.0f;
    r.scale = Vec2(u(rng), u(rng));
    return r;
}

scene::Material random_material(std::mt19937& rng, int textures) {
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const auto pick = [&](float v) {
        // Exact 0 and 1 select the narrow closure nodes; cover them often.
        const uint32_t k = rng() % 4;
        return k == 0 ? 0.0f : k == 1 ? 1.0f : v;
    };
    scene::Material m;
    m.base_color = Rgb(u(rng), u(rng), u(rng));
    m.base_color_texture = random_ref(rng, textures);
    m.metallic = pick(u(rng));
    m.roughness = u(rng);
    m.metallic_roughness_texture = random_ref(rng, textures);
    m.specular = pick(u(rng));
    m.specular_texture = random_ref(rng, textures);
    m.specular_color = Rgb(2.0f * u(rng), u(rng), u(rng));
    m.specular_color_texture = random_ref(rng, textures);
    m.ior = 1.0f + u(rng);
    m.emissive = rng() % 2 ? Rgb(u(rng), u(rng), 2.0f * u(rng)) : Rgb(0.0f);
    m.emissive_strength = 1.0f + 10.0f * u(rng);
    m.emissive_texture = random_ref(rng, textures);
    m.normal_texture = random_ref(rng, textures);
    m.normal_scale = 2.0f * u(rng);
    return m;
}

Vec3 random_direction(std::mt19937& rng) {
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const float z = u(rng);
    const float phi = 2.0f * kPi * u(rng);
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    return Vec3(r * std::cos(phi), r * std::sin(phi), z);
}

// Same BRDF values: the graph's closure and resolve_closure's, through Bsdf::eval. The two
// differ only in the order of float multiplications (factor · texel): relative 1e-5.
TEST(MaterialGraph, EvaluatesAsResolveClosure) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-3.0f, 3.0f);
    std::vector<scene::Texture> textures;
    for (int i = 0; i < 4; ++i)
        textures.push_back(random_texture(rng));
    for (int trial = 0; trial < 2000; ++trial) {
        const scene::Material m = random_material(rng, int(textures.size()));
        const MaterialGraph g = graph_from_gltf(m);
        SurfacePoint p;
        p.uv0 = Vec2(u(rng), u(rng));
        p.uv1 = Vec2(u(rng), u(rng));
        p.frame = Frame(glm::normalize(Vec3(u(rng), u(rng), u(rng)) + Vec3(0.0f, 0.0f, 0.01f)));
        const SurfaceUv uv{p.uv0, p.uv1};
        const ClosureParams expected = resolve_closure(m, textures, uv);
        const ClosureParams got = evaluate_closure(g, textures, p);
        EXPECT_EQ(closure_type(expected), closure_type(got));
        const Bsdf a(expected);
        const Bsdf b(got);
        for (int k = 0; k < 4; ++k) {
            const Vec3 wo = random_direction(rng);
            const Vec3 wi = random_direction(rng);
            const Rgb fa = a.eval(wo, wi);
            const Rgb fb = b.eval(wo, wi);
            for (int c = 0; c < 3; ++c)
                ASSERT_NEAR(fa[c], fb[c], 1e-5f * std::max(1.0f, std::abs(fa[c]))) << trial;
        }
        const Rgb ea = resolve_emission(m, textures, uv);
        const Rgb eb = evaluate_emission(g, textures, p);
        for (int c = 0; c < 3; ++c)
            ASSERT_NEAR(ea[c], eb[c], 1e-5f * std::max(1.0f, ea[c])) << trial;
        const Vec3 na = apply_normal_map(m, textures, uv, p.frame);
        const Vec3 nb = evaluate_normal(g, textures, p);
        ASSERT_NEAR(glm::length(na - nb), 0.0f, 1e-5f) << trial;
    }
}

TEST(MaterialGraph, PicksTheNarrowestClosureNode) {
    scene::Material m;
    m.metallic = 0.0f;
    m.specular = 0.0f;
    EXPECT_EQ(graph_from_gltf(m).nodes[size_t(graph_from_gltf(m).closure)].kind,
              &node_kind("lambertian"));
    m.specular = 1.0f;
    MaterialGraph g = graph_from_gltf(m);
    EXPECT_EQ(g.nodes[size_t(g.closure)].kind, &node_kind("dielectric_diffuse"));
    m.metallic = 1.0f;
    g = graph_from_gltf(m);
    EXPECT_EQ(g.nodes[size_t(g.closure)].kind, &node_kind("ggx_conductor"));
    m.metallic = 0.5f;
    g = graph_from_gltf(m);
    EXPECT_EQ(g.nodes[size_t(g.closure)].kind, &node_kind("metal_rough"));
    m.metallic = 0.0f;
    m.transmission = 1.0f;
    g = graph_from_gltf(m);
    EXPECT_EQ(g.nodes[size_t(g.closure)].kind, &node_kind("rough_dielectric"));
    // The reflection lobe alone: a black base.
    EXPECT_EQ(evaluate_closure(g, {}, SurfacePoint{}).base_color, Rgb(0.0f));
    // The transmission (CPU only): t · base colour, thin without KHR_materials_volume.
    EXPECT_EQ(evaluate_closure(g, {}, SurfacePoint{}).transmission, m.base_color);
    EXPECT_TRUE(evaluate_closure(g, {}, SurfacePoint{}).thin_walled);
    m.thickness = 0.1f;
    EXPECT_FALSE(evaluate_closure(graph_from_gltf(m), {}, SurfacePoint{}).thin_walled);
    m.thickness = 0.0f;
    m.transmission = 0.25f;
    m.base_color = Rgb(0.8f);
    g = graph_from_gltf(m);
    const std::vector<const NodeKind*> kinds = g.kinds();
    EXPECT_TRUE(std::count(kinds.begin(), kinds.end(), &node_kind("mix_node")) == 1);
    EXPECT_NEAR(evaluate_closure(g, {}, SurfacePoint{}).base_color.r, 0.6f, 1e-6f);
    EXPECT_NEAR(evaluate_closure(g, {}, SurfacePoint{}).transmission.r, 0.2f, 1e-6f);
}

// COLOR_0 (issue 12): the base colour, alpha included, times the vertex colour in graphs of
// materials that a mesh with COLOR_0 uses; other graphs have no vertex-colour node.
TEST(MaterialGraph, VertexColourMultipliesTheBaseColourAndAlpha) {
    scene::Material m;
    m.metallic = 0.0f;
    m.base_color = Rgb(0.5f, 0.8f, 1.0f);
    m.base_alpha = 0.6f;
    m.alpha_mode = scene::AlphaMode::Mask;
    SurfacePoint p;
    p.color = Vec4(1.0f, 0.5f, 0.0f, 0.5f);
    const MaterialGraph plain = graph_from_gltf(m);
    const std::vector<const NodeKind*> plain_kinds = plain.kinds();
    EXPECT_EQ(std::count(plain_kinds.begin(), plain_kinds.end(), &node_kind("vertex_color")), 0);
    EXPECT_EQ(evaluate_closure(plain, {}, p).base_color, m.base_color);
    EXPECT_NEAR(evaluate_input(plain, plain.alpha, {}, p).x, 0.6f, 1e-6f);

    const MaterialGraph coloured = graph_from_gltf(m, {.vertex_colors = true});
    const std::vector<const NodeKind*> kinds = coloured.kinds();
    EXPECT_EQ(std::count(kinds.begin(), kinds.end(), &node_kind("vertex_color")), 1);
    const Rgb base = evaluate_closure(coloured, {}, p).base_color;
    EXPECT_NEAR(base.r, 0.5f, 1e-6f);
    EXPECT_NEAR(base.g, 0.4f, 1e-6f);
    EXPECT_NEAR(base.b, 0.0f, 1e-6f);
    EXPECT_NEAR(evaluate_input(coloured, coloured.alpha, {}, p).x, 0.3f, 1e-6f);
    EXPECT_TRUE(coloured.masked());
    m.alpha_mode = scene::AlphaMode::Opaque;
    EXPECT_FALSE(graph_from_gltf(m, {.vertex_colors = true}).masked());
}

TEST(MaterialGraph, BumpMapTiltsAgainstTheHeightGradient) {
    // h = u along a 2-texel ramp: the normal leans towards −tangent.
    scene::Texture ramp;
    ramp.width = 4;
    ramp.height = 1;
    ramp.filter = scene::Filter::Linear;
    ramp.wrap_s = scene::Wrap::ClampToEdge;
    for (int i = 0; i < 4; ++i)
        ramp.texels.emplace_back(float(i) / 4.0f);
    MaterialGraph g;
    Node t;
    t.kind = &node_kind("image_texture");
    t.texture.texture = 0;
    const int height = g.add(t);
    Node bump;
    bump.kind = &node_kind("bump_map");
    bump.value = Vec4(0.5f);
    bump.inputs[0] = {height, 0};
    g.normal = g.add(bump);
    SurfacePoint p;
    p.uv0 = Vec2(0.5f, 0.5f);
    const Vec3 n = evaluate_normal(g, {ramp}, p);
    // dh/du = 1 over the ramp's interior: n ∝ (−0.5, 0, 1).
    EXPECT_NEAR(n.x, -0.5f / std::sqrt(1.25f), 1e-4f);
    EXPECT_NEAR(n.y, 0.0f, 1e-6f);
}

TEST(GlslModule, EmitsDependenciesFirstAndOnce) {
    GlslModule m;
    m.require("metal_rough_eval");
    m.require("ggx_conductor_eval");
    m.require("metal_rough_eval");
    const std::vector<std::string>& f = m.functions();
    const auto pos = [&](const std::string& name) {
        return std::find(f.begin(), f.end(), name) - f.begin();
    };
    for (const std::string& name : f)
        EXPECT_EQ(std::count(f.begin(), f.end(), name), 1) << name;
    // Fresnel and the GGX terms come with shaders/shared/shading_math.h, after its constants.
    EXPECT_LT(pos("constants"), pos("shading_math"));
    EXPECT_LT(pos("shading_math"), pos("fresnel_schlick"));
    EXPECT_LT(pos("ggx_d"), pos("ggx_reflection"));
    EXPECT_LT(pos("ggx_reflection"), pos("metal_rough_eval"));
    EXPECT_LT(pos("metal_rough_eval"), pos("ggx_conductor_eval"));
    EXPECT_THROW(m.require("no_such_function"), std::logic_error);
}

TEST(MaterialCodegen, OneFunctionPerMaterialNamedAfterItsNodes) {
    scene::Material diffuse;
    diffuse.metallic = 0.0f;
    diffuse.specular = 0.0f;
    scene::Material textured = diffuse;
    textured.base_color_texture.texture = 0;
    scene::Texture tex;
    tex.width = tex.height = 1;
    tex.texels = {Vec4(0.5f)};
    const MaterialCode a = generate_material_code({graph_from_gltf(diffuse)}, {tex}, 3);
    EXPECT_EQ(a.bindings, "");
    EXPECT_EQ(a.functions.find("sampler2D"), std::string::npos);
    EXPECT_NE(a.functions.find("void material_0("), std::string::npos);
    EXPECT_NE(a.functions.find("lambertian("), std::string::npos);
    const MaterialCode b =
        generate_material_code({graph_from_gltf(diffuse), graph_from_gltf(textured)}, {tex}, 3);
    EXPECT_EQ(b.bindings, "layout(set = 0, binding = 3) uniform sampler2D texture_0;\n");
    EXPECT_EQ(b.textures, std::vector<int>{0});
    EXPECT_NE(b.functions.find("image_texture(texture_0, s.uv0"), std::string::npos);
}

// Code grows with the distinct materials drawn: a repeated material shares its twin's function
// (and dispatches through it), an unused one gets none.
TEST(MaterialCodegen, SharesIdenticalMaterialsAndSkipsUnusedOnes) {
    scene::Material grey;
    grey.metallic = 0.0f;
    grey.specular = 0.0f;
    grey.base_color = Rgb(0.5f);
    scene::Material dark = grey;
    dark.base_color = Rgb(0.2f);
    const std::vector<MaterialGraph> graphs = {graph_from_gltf(grey), graph_from_gltf(dark),
                                               graph_from_gltf(grey)};
    const MaterialCode all = generate_material_code(graphs, {}, 0);
    EXPECT_NE(all.functions.find("void material_0("), std::string::npos);
    EXPECT_NE(all.functions.find("void material_1("), std::string::npos);
    EXPECT_EQ(all.functions.find("void material_2("), std::string::npos);
    EXPECT_NE(all.functions.find("case 1u: material_1("), std::string::npos);
    EXPECT_EQ(all.functions.find("case 2u:"), std::string::npos);  // material_0's, the default
    const MaterialCode some = generate_material_code(graphs, {}, 0, true, {false, true, true});
    EXPECT_EQ(some.functions.find("void material_0("), std::string::npos);
    EXPECT_NE(some.functions.find("void material_1("), std::string::npos);
    EXPECT_NE(some.functions.find("case 2u: material_2("), std::string::npos);
    EXPECT_NE(some.functions.find("default: material_1("), std::string::npos);
}

}  // namespace
}  // namespace mvpl::material
