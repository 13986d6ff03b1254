// The shader chain leaves out what a scene does not need (docs/design.md, "Shader chain"): the
// Cornell box (diffuse, one area light) gets no microfacet code, no 2D sampler and no code for
// light types it has not; one more textured, glossy material adds exactly its nodes. And the
// SPIR-V cache: hits, and a corrupt or unwritable cache never fails a compile.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>

#include "engine/gpu/shader_compiler.h"
#include "engine/gpu/spirv_cache.h"
#include "engine/material/material_codegen.h"
#include "engine/render/closed_surface.h"
#include "engine/render/shader_program.h"
#include "engine/scene/scene_loader.h"

namespace mvpl::render {
namespace {

const std::string kCornell = std::string(MVPL_ASSETS_DIR) + "/cornell-box/cbox.gltf";

std::set<std::string> as_set(const std::vector<std::string>& v) {
    return {v.begin(), v.end()};
}

std::set<std::string> minus(const std::set<std::string>& a, const std::set<std::string>& b) {
    std::set<std::string> out;
    std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::inserter(out, out.end()));
    return out;
}

bool contains(const std::string& text, const std::string& what) {
    return text.find(what) != std::string::npos;
}

// Materials no mesh draws with add no code: the Cornell box with 1000 more (glossy, textured,
// each different) generates the same stages as without them (issue 19: start-up time grew with
// the materials a file lists).
TEST(ShaderProgram, UnusedMaterialsAddNoCode) {
    const scene::Scene cornell = scene::load_scene(kCornell);
    scene::Scene padded = cornell;
    scene::Texture tex;
    tex.width = tex.height = 1;
    tex.texels = {Vec4(0.5f)};
    padded.textures.push_back(tex);
    for (int i = 0; i < 1000; ++i) {
        scene::Material m;
        m.base_color = Rgb(float(i) / 1000.0f);
        m.roughness = 0.3f;
        m.base_color_texture.texture = int(padded.textures.size()) - 1;
        padded.materials.push_back(m);
    }
    const SceneShaders a = generate_scene_shaders(cornell, {});
    const SceneShaders b = generate_scene_shaders(padded, {});
    ASSERT_EQ(a.stages().size(), b.stages().size());
    for (size_t i = 0; i < a.stages().size(); ++i)
        EXPECT_EQ(a.stages()[i]->source, b.stages()[i]->source) << a.stages()[i]->name;
}

TEST(ShaderProgram, CornellBoxHasNoMicrofacetCodeNoSamplerAndOnlyItsLightTypes) {
    const scene::Scene scene = scene::load_scene(kCornell);
    const SceneShaders s = generate_scene_shaders(scene, {});
    for (const StageSource* stage : s.stages()) {
        EXPECT_FALSE(contains(stage->source, "ggx")) << stage->name;
        EXPECT_FALSE(contains(stage->source, "fresnel")) << stage->name;
        EXPECT_FALSE(contains(stage->source, "sampler2D")) << stage->name;
        EXPECT_FALSE(contains(stage->source, "#include")) << stage->name;
    }
    const ShaderFeatures& f = s.features;
    EXPECT_TRUE(f.has(light::VplType::Area));
    EXPECT_TRUE(f.has(light::VplType::Surface));
    EXPECT_FALSE(f.has(light::VplType::Point));
    EXPECT_FALSE(f.has(light::VplType::Spot));
    EXPECT_FALSE(f.has(light::VplType::Directional));
    EXPECT_FALSE(contains(s.shading_comp.source, "spot_falloff"));
    EXPECT_FALSE(contains(s.shading_comp.source, "directional_visibility"));
    EXPECT_TRUE(contains(s.shading_comp.source, "lambertian_eval"));
    EXPECT_FALSE(contains(s.shading_comp.source, "metal_rough_eval"));
    // No lobe-wise clamp (issue 15): a diffuse pair has nothing to release.
    EXPECT_FALSE(contains(s.shading_comp.source, "closure_eval_diffuse"));
    EXPECT_FALSE(contains(s.shading_comp.source, "vsl_glossy_d2"));
    // Depth 2 (direct light only): no surface VPL, so no closure of a VPL is evaluated.
    const SceneShaders direct = generate_scene_shaders(scene, ShaderOptions{false});
    EXPECT_FALSE(contains(direct.shading_comp.source, "e.f = closure_eval"));
    EXPECT_FALSE(contains(direct.shading_comp.source, "v.closure_type"));
    // One function per material, named after it; the closure node named after its kind.
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        EXPECT_TRUE(contains(s.g_buffer_frag.source, "void material_" + std::to_string(i) + "("));
    }
    EXPECT_TRUE(contains(s.g_buffer_frag.source, "c = lambertian("));
}

// The shadow test's junction lookup (thin walls) comes with a zero-thickness occluder only: an
// open mesh (one-sided or not), or a drawn double-sided material. The Cornell box's solids alone
// do without it; its floor, an open quad, adds it; a double-sided material that no
// mesh draws adds nothing; one that a mesh draws adds it.
TEST(ShaderProgram, OnlyScenesWithZeroThicknessOccludersGetTheJunctionLookup) {
    const scene::Scene cornell = scene::load_scene(kCornell);
    scene::Scene scene = cornell;
    scene.meshes.clear();
    for (const scene::Mesh& m : cornell.meshes) {
        if (bounds_solid(m)) scene.meshes.push_back(m);
    }
    ASSERT_FALSE(scene.meshes.empty());  // a box
    const std::string junction = "kJunctionReach * footprint";
    EXPECT_FALSE(generate_scene_shaders(scene, {}).features.thin_walls);
    EXPECT_FALSE(contains(generate_scene_shaders(scene, {}).shading_comp.source, junction));
    scene.materials.push_back(scene.materials[size_t(scene.meshes[0].material)]);
    scene.materials.back().double_sided = true;
    EXPECT_FALSE(contains(generate_scene_shaders(scene, {}).shading_comp.source, junction));
    scene::Scene with_double_sided = scene;
    with_double_sided.meshes[0].material = int(scene.materials.size()) - 1;
    const SceneShaders double_sided = generate_scene_shaders(with_double_sided, {});
    EXPECT_TRUE(double_sided.features.thin_walls);
    EXPECT_TRUE(contains(double_sided.shading_comp.source, junction));
    scene.meshes.push_back(cornell.meshes[1]);  // the floor
    ASSERT_FALSE(bounds_solid(scene.meshes.back()));
    const SceneShaders with_floor = generate_scene_shaders(scene, {});
    EXPECT_TRUE(with_floor.features.thin_walls);
    EXPECT_TRUE(contains(with_floor.shading_comp.source, junction));
}

TEST(ShaderProgram, ATexturedGlossyMaterialAddsExactlyItsNodes) {
    const scene::Scene cornell = scene::load_scene(kCornell);
    scene::Scene scene = cornell;
    scene::Texture tex;
    tex.width = tex.height = 2;
    tex.texels.assign(4, Vec4(0.5f));
    scene.textures.push_back(tex);
    scene::Material glossy;
    glossy.metallic = 0.0f;
    glossy.roughness = 0.3f;
    glossy.base_color_texture.texture = int(scene.textures.size()) - 1;
    glossy.normal_texture.texture = int(scene.textures.size()) - 1;
    scene.materials.push_back(glossy);
    scene.meshes.push_back(cornell.meshes.front());
    scene.meshes.back().material = int(scene.materials.size()) - 1;

    const auto graphs = [](const scene::Scene& s) {
        std::vector<material::MaterialGraph> g;
        for (const scene::Material& m : s.materials)
            g.push_back(material::graph_from_gltf(m));
        return g;
    };
    const material::MaterialCode before =
        material::generate_material_code(graphs(cornell), cornell.textures, 0);
    const material::MaterialCode after =
        material::generate_material_code(graphs(scene), scene.textures, 0);
    // What the new material's nodes need on their own.
    const material::MaterialGraph g = material::graph_from_gltf(glossy);
    material::GlslModule alone;
    alone.require("Closure");
    alone.require("SurfacePoint");
    for (const material::NodeKind* kind : g.kinds()) {
        if (kind != &material::node_kind("constant")) alone.require(kind->name);
    }
    const std::set<std::string> b = as_set(before.node_functions);
    const std::set<std::string> a = as_set(after.node_functions);
    EXPECT_TRUE(minus(b, a).empty());
    EXPECT_EQ(minus(a, b), minus(as_set(alone.functions()), b));
    EXPECT_EQ(minus(a, b),
              (std::set<std::string>{"dielectric_diffuse", "image_texture", "normal_map"}));
    EXPECT_EQ(after.textures, std::vector<int>{0});
    EXPECT_TRUE(contains(after.bindings, "uniform sampler2D texture_0;"));

    // The shading shader gains exactly the dielectric evaluator and what it needs.
    std::vector<std::string> shading_before;
    std::vector<std::string> shading_after;
    generate_shading_source(scene_features(cornell, {}), &shading_before);
    generate_shading_source(scene_features(scene, {}), &shading_after);
    const std::set<std::string> added = minus(as_set(shading_after), as_set(shading_before));
    EXPECT_TRUE(added.contains("dielectric_diffuse_eval"));
    EXPECT_TRUE(added.contains("ggx_d"));
    EXPECT_FALSE(added.contains("ggx_conductor_eval"));
    EXPECT_TRUE(minus(as_set(shading_before), as_set(shading_after)).empty());
}

// The shading template's `//@if` blocks cut across its functions (a VPL type's code, the glossy
// lobes, the chains, the junction lookup): every combination that a scene can ask for must still
// be a program glslang accepts, not only those of the scenes the GPU tests render.
TEST(ShaderProgram, EveryVariantOfTheShadingProgramCompiles) {
    for (uint32_t mask = 1; mask < (1u << kVplTypeCount); ++mask) {
        for (uint32_t flags = 0; flags < 8; ++flags) {
            ShaderFeatures f;
            for (int t = 0; t < kVplTypeCount; ++t)
                f.vpl_types[size_t(t)] = (mask >> t & 1u) != 0;
            f.closure_types.fill((flags & 1u) != 0);  // microfacet closures: glossy()
            f.closure_types[size_t(material::ClosureType::Lambertian)] = true;
            f.thin_walls = (flags & 2u) != 0;
            f.specular_chains = (flags & 4u) != 0;
            const StageSource s = generate_shading_source(f);
            EXPECT_NO_THROW(gpu::compile_glsl(gpu::ShaderStage::compute, s.source, s.name))
                << "VPL types " << mask << ", flags " << flags;
        }
    }
}

TEST(ShaderProgram, TemplatesKeepOnlyEnabledBlocks) {
    const std::string t = "a\n//@if x|y\nb\n//@endif\n//@if z\nc\n//@endif\n//@insert w\nd\n";
    EXPECT_EQ(expand_template(t, {"y"}, {{"w", "W\n"}}), "a\nb\nW\nd\n");
    EXPECT_EQ(expand_template(t, {"z"}, {{"w", ""}}), "a\nc\nd\n");
}

class SpirvCacheTest : public ::testing::Test {
protected:
    void SetUp() override {
        m_dir = std::filesystem::temp_directory_path() /
                ("mvpl-spirv-cache-test-" +
                 std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
                 ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::remove_all(m_dir);
    }
    void TearDown() override { std::filesystem::remove_all(m_dir); }
    std::filesystem::path m_dir;
};

constexpr const char* kCompute =
    "#version 460\nlayout(local_size_x = 1) in;\nlayout(set = 0, binding = 0) buffer B { float "
    "x[]; };\n"
    "void main() { x[0] = 1.0; }\n";

TEST_F(SpirvCacheTest, SecondCompileIsAHitWithTheSameWords) {
    const gpu::SpirvCacheOptions options{true, m_dir};
    bool hit = true;
    const auto a =
        gpu::compile_glsl_cached(gpu::ShaderStage::compute, kCompute, "t.comp", options, &hit);
    EXPECT_FALSE(hit);
    const auto b =
        gpu::compile_glsl_cached(gpu::ShaderStage::compute, kCompute, "t.comp", options, &hit);
    EXPECT_TRUE(hit);
    EXPECT_EQ(a, b);
    // The key covers the stage and the source.
    EXPECT_NE(gpu::spirv_cache_key(gpu::ShaderStage::compute, kCompute),
              gpu::spirv_cache_key(gpu::ShaderStage::vertex, kCompute));
    EXPECT_NE(gpu::spirv_cache_key(gpu::ShaderStage::compute, kCompute),
              gpu::spirv_cache_key(gpu::ShaderStage::compute, std::string(kCompute) + " "));
    // Disabled: never a hit.
    gpu::compile_glsl_cached(gpu::ShaderStage::compute, kCompute, "t.comp", {false, m_dir}, &hit);
    EXPECT_FALSE(hit);
}

TEST_F(SpirvCacheTest, CorruptEntriesAreRecompiledAndRewritten) {
    const gpu::SpirvCacheOptions options{true, m_dir};
    const auto good =
        gpu::compile_glsl_cached(gpu::ShaderStage::compute, kCompute, "t.comp", options);
    const std::filesystem::path entry =
        m_dir / (gpu::spirv_cache_key(gpu::ShaderStage::compute, kCompute) + ".spv");
    ASSERT_TRUE(std::filesystem::exists(entry));
    const auto size = std::filesystem::file_size(entry);
    for (const auto damage : {0, 1, 2}) {
        if (damage == 0) std::filesystem::resize_file(entry, size / 2);  // truncated
        if (damage == 1) {                                               // a flipped bit
            std::fstream f(entry, std::ios::in | std::ios::out | std::ios::binary);
            f.seekp(std::streamoff(size - 5));
            f.put('\x5a');
        }
        if (damage == 2) std::ofstream(entry, std::ios::trunc) << "garbage";
        bool hit = true;
        const auto again =
            gpu::compile_glsl_cached(gpu::ShaderStage::compute, kCompute, "t.comp", options, &hit);
        EXPECT_FALSE(hit) << damage;
        EXPECT_EQ(again, good) << damage;
        EXPECT_EQ(std::filesystem::file_size(entry), size) << damage;  // rewritten whole
    }
}

TEST_F(SpirvCacheTest, AnUnwritableCacheStillCompiles) {
    // A regular file where the directory should be: nothing can be created below it.
    std::ofstream(m_dir) << "not a directory";
    bool hit = true;
    const auto words = gpu::compile_glsl_cached(gpu::ShaderStage::compute, kCompute, "t.comp",
                                                {true, m_dir / "sub"}, &hit);
    EXPECT_FALSE(hit);
    EXPECT_FALSE(words.empty());
    std::filesystem::remove(m_dir);
}

}  // namespace
}  // namespace mvpl::render
