// glTF alphaMode (issue 12) on the GPU: MASK cuts in the G-buffer and the shadow maps as
// Embree's filters cut on the CPU; BLEND is hashed transparency covering a fraction alpha, in
// the G-buffer and in the shadow maps.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "engine/core/image_metrics.h"
#include "engine/gpu/command_list.h"
#include "engine/material/scene_materials.h"
#include "engine/render/g_buffer_pass.h"
#include "engine/render/scene_geometry.h"
#include "engine/render/shader_program.h"
#include "engine/scene/camera.h"
#include "engine/trace/accel.h"
#include "tests/gpu/gpu_test.h"
#include "tests/support/scene_builder.h"
#include "tests/support/vpl_render.h"

namespace mvpl::render {
namespace {

using GltfAlphaTest = gpu::testing::GpuTest;

constexpr uint32_t kRes = 48;

GBufferSources generate_scene_shaders_g_buffer(const scene::Scene& s) {
    const material::SceneMaterials materials(s);
    return generate_g_buffer_sources(materials.graphs(), s.textures, s.drawn_materials());
}

std::vector<GBufferTexel> g_buffer(gpu::Context& context, const scene::Scene& s) {
    const SceneGeometry geometry(context, s);
    GBufferPass pass(context, geometry, kRes, kRes);
    context.submit_and_wait([&](gpu::CommandList& cmd) { pass.record(cmd, s.camera); });
    return pass.download();
}

// Two masked quads in front of an opaque one (material 2): the left cut by its texture's alpha
// (0 in the texture's left column, nearest filtering), the right by COLOR_0's alpha (0 on its
// left edge, 1 on its right, cutoff 0.5). Each quad's left half is cut.
scene::Scene masked_quads() {
    scene::Scene s;
    scene::Material textured = test::diffuse_material(Rgb(0.8f));
    textured.alpha_mode = scene::AlphaMode::Mask;
    textured.base_color_texture.texture = 0;
    scene::Material coloured = test::diffuse_material(Rgb(0.6f));
    coloured.alpha_mode = scene::AlphaMode::Mask;
    s.materials = {textured, coloured, test::diffuse_material(Rgb(0.4f))};
    scene::Texture alpha;
    alpha.name = "alpha";
    alpha.width = 2;
    alpha.height = 1;
    alpha.texels = {Vec4(1, 1, 1, 0), Vec4(1, 1, 1, 1)};
    alpha.filter = scene::Filter::Nearest;
    s.textures.push_back(alpha);
    scene::Mesh left = test::make_quad(Vec3(-1.05f, -0.5f, 0.5f), Vec3(1, 0, 0), Vec3(0, 1, 0), 0);
    scene::Mesh right = test::make_quad(Vec3(0.05f, -0.5f, 0.5f), Vec3(1, 0, 0), Vec3(0, 1, 0), 1);
    right.colors = {Vec4(1, 1, 1, 0), Vec4(1, 1, 1, 1), Vec4(1, 1, 1, 1), Vec4(1, 1, 1, 0)};
    scene::Mesh back = test::make_quad(Vec3(-2, -2, 0), Vec3(4, 0, 0), Vec3(0, 4, 0), 2);
    s.meshes = {left, right, back};
    s.camera = test::look_at(Vec3(0, 0, 3), Vec3(0.0f), 0.8f);
    return s;
}

// The G-buffer shows the material that the CPU's camera ray hits (Embree's filter skips cut
// texels) at every pixel but those whose hit on a masked quad lies within 2 % of the cut
// (u = 0.5) or of an edge, where float rounding may fall either way.
TEST_F(GltfAlphaTest, MaskedTexelsShowWhatLiesBehind) {
    const scene::Scene s = masked_quads();
    const std::vector<GBufferTexel> texels = g_buffer(context(), s);
    const trace::Accel accel(s);
    std::array<int, 3> seen{};
    int compared = 0;
    int differ = 0;
    for (uint32_t y = 0; y < kRes; ++y) {
        for (uint32_t x = 0; x < kRes; ++x) {
            const scene::CameraRay r =
                scene::generate_camera_ray(s.camera, kRes, kRes, Vec2(x + 0.5f, y + 0.5f));
            // Where the ray crosses the masked quads' plane z = 0.5, in their uv.
            const Vec3 p = r.origin + r.direction * ((0.5f - r.origin.z) / r.direction.z);
            const float u = p.x < 0.0f ? p.x + 1.05f : p.x - 0.05f;
            const float v = p.y + 0.5f;
            const auto near = [](float a, float b) { return std::abs(a - b) < 0.02f; };
            if (near(u, 0.0f) || near(u, 0.5f) || near(u, 1.0f) || near(v, 0.0f) || near(v, 1.0f))
                continue;
            const std::optional<trace::Hit> hit = accel.intersect_camera({r.origin, r.direction});
            const GBufferTexel& t = texels[y * kRes + x];
            ASSERT_TRUE(hit && t.covered) << x << "," << y;
            const int expected = s.meshes[size_t(hit->mesh)].material;
            ++compared;
            ++seen[size_t(expected)];
            if (int(t.material) != expected && differ++ < 5)
                ADD_FAILURE() << "pixel " << x << "," << y << ": G-buffer material " << t.material
                              << ", CPU " << expected;
        }
    }
    EXPECT_EQ(differ, 0) << "of " << compared;
    // Both masked quads show their kept halves, and the back quad shows through the cut ones.
    EXPECT_GT(seen[0], 50);
    EXPECT_GT(seen[1], 50);
    EXPECT_GT(seen[2], seen[0] + seen[1]);
}

// A floor under a masked quad (texture alpha: the half at z < 0 cut) lit from above by a point
// or a directional light: the cut half casts no shadow.
scene::Scene masked_shadow_scene(bool directional) {
    scene::Scene s;
    scene::Material masked = test::diffuse_material(Rgb(0.7f));
    masked.alpha_mode = scene::AlphaMode::Mask;
    masked.base_color_texture.texture = 0;
    s.materials = {test::diffuse_material(Rgb(0.8f)), masked};
    scene::Texture alpha;
    alpha.name = "alpha";
    alpha.width = 2;
    alpha.height = 1;
    alpha.texels = {Vec4(1, 1, 1, 0), Vec4(1, 1, 1, 1)};
    alpha.filter = scene::Filter::Nearest;
    s.textures.push_back(alpha);
    s.meshes = {test::make_quad(Vec3(-2, 0, -2), Vec3(0, 0, 4), Vec3(4, 0, 0), 0),
                test::make_quad(Vec3(-1, 1, -1), Vec3(0, 0, 2), Vec3(2, 0, 0), 1)};
    scene::Light light;
    if (directional) {
        light.type = scene::LightType::Directional;
        light.intensity = Rgb(2.0f);
        light.direction = glm::normalize(Vec3(0.2f, -1.0f, 0.1f));
    } else {
        light.type = scene::LightType::Point;
        light.intensity = Rgb(20.0f);
        light.position = Vec3(0.0f, 3.0f, 0.0f);
    }
    s.lights = {light};
    s.camera = test::look_at(Vec3(0, 4, 3.5f), Vec3(0.0f), 0.9f);
    return s;
}

// The shadow maps' alpha test against the oracle's exact (filtered) visibility, direct light
// only. The two differ only where a shadow texel decides visibility differently from Embree: a
// band along the shadow's outline (the kept half's, 6 m long) of 1.25 texels (as in
// test_textured_scene.cpp), a texel being at most 0.03 m on the floor (the point light's cube:
// 3 m × 2/256 at ≤ 35° incidence; the directional map: a window of the scene's 5.7 m diagonal over
// 256 texels). The mean absolute difference is then at most the band's share of the 16 m² lit
// floor, 6 × 1.25 × 0.03 / 16 = 1.4 % of the image mean (relMSE would not do: one pixel that
// is black in one image and lit in the other weighs 25/pixel count). Measured: 0 (point light),
// 0.2 % (directional). The same scene drawn opaque into the shadow maps (the cut half then
// shadows 2 m² of the floor; measured 25 % and 4.7 %) must be beyond twice the bound: the test
// sees the alpha test.
double mean_difference(const Image& image, const Image& reference) {
    const Rgb mean = reference.mean();
    return compare_images(image, reference).mean_abs / ((mean.r + mean.g + mean.b) / 3.0);
}

TEST_F(GltfAlphaTest, MaskedShadowsAgreeWithTheOracle) {
    constexpr double kBound = 6.0 * 1.25 * 0.03 / 16.0;
    for (const bool directional : {false, true}) {
        const char* name = directional ? "directional" : "point";
        const scene::Scene s = masked_shadow_scene(directional);
        const light::VplSet vpls = test::monte_carlo_vpls(s, 4, 2, 1);
        const test::VplRenderSettings settings{.res = 48, .shadow_res = 256, .clamp = 0.0f};
        const Image oracle = test::oracle_render(s, vpls, settings);
        const double error =
            mean_difference(test::gpu_render(context(), s, vpls, settings), oracle);
        EXPECT_LT(error, kBound) << name;
        scene::Scene opaque = s;
        opaque.materials[1].alpha_mode = scene::AlphaMode::Opaque;
        const double unmasked =
            mean_difference(test::gpu_render(context(), opaque, vpls, settings), oracle);
        EXPECT_GT(unmasked, 2.0 * kBound) << name;
        RecordProperty(std::string("difference_") + name, std::to_string(error));
        RecordProperty(std::string("difference_opaque_") + name, std::to_string(unmasked));
    }
}

// BLEND as hashed transparency in the G-buffer: a blended quad of alpha 0.3 in front of an
// opaque one covers a fraction 0.3 of the pixels (binomial over 48² pixels: σ = 0.0095, 5σ), in
// another pattern at another sub-pixel position.
TEST_F(GltfAlphaTest, BlendCoversAFractionAlphaOfThePixels) {
    scene::Scene s = masked_quads();
    s.materials[1].alpha_mode = scene::AlphaMode::Blend;
    s.materials[1].base_alpha = 0.3f;
    s.meshes[1] = test::make_quad(Vec3(-1.5f, -1.5f, 0.5f), Vec3(3, 0, 0), Vec3(0, 3, 0), 1);
    s.meshes.erase(s.meshes.begin());
    const SceneGeometry geometry(context(), s);
    GBufferPass pass(context(), geometry, kRes, kRes);
    std::vector<bool> first;
    for (const Vec2 subpixel : {Vec2(0.5f), Vec2(0.25f, 0.75f)}) {
        context().submit_and_wait(
            [&](gpu::CommandList& cmd) { pass.record(cmd, s.camera, subpixel); });
        const std::vector<GBufferTexel> texels = pass.download();
        int blended = 0;
        std::vector<bool> pattern;
        for (const GBufferTexel& t : texels) {
            ASSERT_TRUE(t.covered);
            pattern.push_back(t.material == 1);
            blended += t.material == 1 ? 1 : 0;
        }
        EXPECT_NEAR(double(blended) / texels.size(), 0.3, 0.048);
        if (first.empty()) {
            first = pattern;
        } else {
            EXPECT_NE(first, pattern);
        }
    }
}

// BLEND's shadows: a blended quad of alpha 0.5 over the floor of masked_shadow_scene shadows half
// of the light that it would shadow opaque. The GPU draws it into each VPL's shadow map with
// another hash pattern; the oracle traces one shadow ray per VPL and pixel, and the VPLs of a
// point light coincide, so each of its pixels is lit or not. The image means agree within the
// oracle's binomial noise: ~60 % of the floor is in the shadow, ~1100 pixels of 48², each lit
// with probability 0.5, so σ ≈ 0.6 · √(0.25 / 1100) ≈ 0.9 % of the unshadowed level, 1.3 % of
// the mean: 4 % is 3σ. The quad drawn opaque (measured 44 % darker) is far beyond it.
TEST_F(GltfAlphaTest, BlendShadowsAFractionAlphaOfTheLight) {
    scene::Scene s = masked_shadow_scene(false);
    s.materials[1].alpha_mode = scene::AlphaMode::Blend;
    s.materials[1].base_alpha = 0.5f;
    s.materials[1].base_color_texture = {};
    // Facing down, one-sided: the camera sees through it, the light does not (shadows keep
    // back faces), so the image is the floor's alone.
    s.meshes[1] = test::make_quad(Vec3(-1, 1, -1), Vec3(2, 0, 0), Vec3(0, 0, 2), 1);
    const light::VplSet vpls = test::monte_carlo_vpls(s, 32, 2, 1);
    const test::VplRenderSettings settings{.res = 48, .shadow_res = 256, .clamp = 0.0f};
    const Rgb oracle = test::oracle_render(s, vpls, settings).mean();
    const Rgb gpu = test::gpu_render(context(), s, vpls, settings).mean();
    EXPECT_NEAR(gpu.r / oracle.r, 1.0, 0.04);
    scene::Scene opaque = s;
    opaque.materials[1].alpha_mode = scene::AlphaMode::Opaque;
    const Rgb dark = test::gpu_render(context(), opaque, vpls, settings).mean();
    EXPECT_LT(dark.r / oracle.r, 0.9);
    RecordProperty("gpu_over_oracle", std::to_string(gpu.r / oracle.r));
    RecordProperty("opaque_over_oracle", std::to_string(dark.r / oracle.r));
}

// Only scenes that draw a masked material get the alpha test (and texture bindings in the
// G-buffer's fragment stage).
TEST(GltfAlphaShaders, AlphaTestOnlyInMaskedScenes) {
    scene::Scene s = masked_quads();
    GBufferSources g = generate_scene_shaders_g_buffer(s);
    EXPECT_NE(g.frag.source.find("alpha_cut("), std::string::npos);
    EXPECT_EQ(g.fragment_textures.size(), 1u);
    const material::SceneMaterials materials(s);
    EXPECT_NE(generate_shadow_alpha_sources(materials.graphs(), s.textures, s.drawn_materials())
                  .frag.source.find("alpha_cut("),
              std::string::npos);
    for (scene::Material& m : s.materials)
        m.alpha_mode = scene::AlphaMode::Opaque;
    g = generate_scene_shaders_g_buffer(s);
    EXPECT_EQ(g.frag.source.find("alpha_cut"), std::string::npos);
    EXPECT_TRUE(g.fragment_textures.empty());
    const material::SceneMaterials opaque(s);
    EXPECT_TRUE(generate_shadow_alpha_sources(opaque.graphs(), s.textures, s.drawn_materials())
                    .frag.name.empty());
}

}  // namespace
}  // namespace mvpl::render
