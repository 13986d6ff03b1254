// glTF as the spec reads (issue 12) in the G-buffer: COLOR_0 multiplies the base colour as the
// CPU's shading points do (with and without the material pass that binds textures), and the
// camera does not see the back faces of one-sided materials.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/core/image_metrics.h"
#include "engine/gpu/command_list.h"
#include "engine/render/g_buffer_pass.h"
#include "engine/render/scene_geometry.h"
#include "engine/render/shader_program.h"
#include "engine/scene/camera.h"
#include "engine/trace/accel.h"
#include "engine/trace/interaction.h"
#include "engine/trace/shading_point.h"
#include "tests/gpu/gpu_test.h"
#include "tests/support/scene_builder.h"
#include "tests/support/vpl_render.h"

namespace mvpl::render {
namespace {

using GltfSpecTest = gpu::testing::GpuTest;

constexpr uint32_t kRes = 48;

std::vector<GBufferTexel> g_buffer(gpu::Context& context, const scene::Scene& s) {
    const SceneGeometry geometry(context, s);
    GBufferPass pass(context, geometry, kRes, kRes);
    context.submit_and_wait([&](gpu::CommandList& cmd) { pass.record(cmd, s.camera); });
    return pass.download();
}

// Two quads side by side facing the camera, each with a red-to-blue COLOR_0 gradient: the left
// one (material 0) untextured, the right one (material 1) with a grey checker texture, so that
// the G-buffer resolves one in its fragment shader and the other in the material pass.
scene::Scene coloured_quads() {
    scene::Scene s;
    s.materials.push_back(test::diffuse_material(Rgb(0.8f)));
    scene::Material textured = test::diffuse_material(Rgb(1.0f));
    textured.base_color_texture.texture = 0;
    s.materials.push_back(textured);
    scene::Texture checker;
    checker.name = "checker";
    checker.width = 2;
    checker.height = 2;
    checker.texels = {Vec4(0.9f), Vec4(0.3f), Vec4(0.3f), Vec4(0.9f)};
    s.textures.push_back(checker);
    const std::vector<Vec4> gradient = {Vec4(1, 0, 0, 1), Vec4(0, 0, 1, 1), Vec4(0, 0, 1, 1),
                                        Vec4(1, 0, 0, 1)};
    scene::Mesh left = test::make_quad(Vec3(-1.05f, -0.5f, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), 0);
    left.colors = gradient;
    scene::Mesh right = test::make_quad(Vec3(0.05f, -0.5f, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), 1);
    right.colors = gradient;
    s.meshes = {left, right};
    s.camera = test::look_at(Vec3(0, 0, 2.5f), Vec3(0.0f), 0.8f);
    return s;
}

// The G-buffer's base colour at every covered pixel against the CPU shading point's at the same
// camera ray (pixels whose hit lies within 2 % of a quad's edge or of a texel edge skipped: the
// rasteriser and Embree may round them apart). Tolerance 1e-3: the interpolated colour and uv
// differ by float rounding only (~1e-6), the checker's bilinear slope amplifies that by ≤ 2.
TEST_F(GltfSpecTest, VertexColoursMultiplyTheBaseColourAsOnTheCpu) {
    const scene::Scene s = coloured_quads();
    const std::vector<GBufferTexel> texels = g_buffer(context(), s);
    const trace::Accel accel(s);
    int compared[2] = {0, 0};
    float worst = 0.0f;
    float reddest = 0.0f;
    float bluest = 0.0f;
    for (uint32_t y = 0; y < kRes; ++y) {
        for (uint32_t x = 0; x < kRes; ++x) {
            const scene::CameraRay r =
                scene::generate_camera_ray(s.camera, kRes, kRes, Vec2(x + 0.5f, y + 0.5f));
            const trace::Ray ray{r.origin, r.direction};
            const std::optional<trace::Hit> hit = accel.intersect_camera(ray);
            const GBufferTexel& t = texels[y * kRes + x];
            if (!hit || !t.covered) continue;  // background, or an edge pixel rounded apart
            const trace::SurfaceInteraction si = trace::make_interaction(s, *hit, ray);
            const Vec2 uv = si.uv0;
            const auto near_edge = [](float v) {
                return std::abs(v - std::round(v * 2.0f) * 0.5f) < 0.02f;
            };
            if (near_edge(uv.x) || near_edge(uv.y)) continue;
            const Rgb expected =
                trace::make_shading_point(accel.materials(), si).bsdf.params().base_color;
            EXPECT_EQ(int(t.material), si.material);
            worst = std::max(worst, glm::length(Vec3(t.closure.base_color - expected)));
            reddest = std::max(reddest, t.closure.base_color.r - t.closure.base_color.b);
            bluest = std::max(bluest, t.closure.base_color.b - t.closure.base_color.r);
            ++compared[si.material];
        }
    }
    EXPECT_GT(compared[0], 100);
    EXPECT_GT(compared[1], 100);
    EXPECT_LT(worst, 1e-3f);
    // Not white: the gradient's ends show (red 0.8·0.98 at best against blue 0.8·0.02).
    EXPECT_GT(reddest, 0.5f);
    EXPECT_GT(bluest, 0.5f);
}

// The coloured quads lit by a point light in front of them: the GPU image against the oracle's
// (same VPLs). Bound as in test_textured_scene.cpp, relMSE below 1.25 · 2/256 (shadow texels
// deciding visibility otherwise than Embree; there is no occluder here, so that is generous);
// the same VPLs on the GPU without COLOR_0 must be far beyond it (the test sees vertex colours).
TEST_F(GltfSpecTest, VertexColouredImageAgreesWithTheOracle) {
    scene::Scene s = coloured_quads();
    scene::Light light;
    light.type = scene::LightType::Point;
    light.intensity = Rgb(8.0f);
    light.position = Vec3(0.0f, 0.5f, 2.0f);
    s.lights = {light};
    const light::VplSet vpls = test::monte_carlo_vpls(s, 8, 3, 1);
    const test::VplRenderSettings settings{.res = 48, .shadow_res = 256};
    const Image oracle = test::oracle_render(s, vpls, settings);
    const double error =
        compare_images(test::gpu_render(context(), s, vpls, settings), oracle).rel_mse;
    constexpr double kBound = 1.25 * 2.0 / 256.0;
    EXPECT_LT(error, kBound);
    scene::Scene plain = s;
    for (scene::Mesh& m : plain.meshes)
        m.colors.clear();
    const double without =
        compare_images(test::gpu_render(context(), plain, vpls, settings), oracle).rel_mse;
    EXPECT_GT(without, 4.0 * kBound);
    RecordProperty("relmse", std::to_string(error));
    RecordProperty("relmse_without_color_0", std::to_string(without));
}

// Only scenes with COLOR_0 get vertex-colour code, and only a textured one hands COLOR_0 to the
// material pass.
TEST(GltfSpecShaders, VertexColourCodeOnlyWhereAMeshHasColor0) {
    scene::Scene s = coloured_quads();
    const auto frag_of = [](const scene::Scene& scene) {
        return generate_scene_shaders(scene, {}).g_buffer_frag.source;
    };
    EXPECT_NE(frag_of(s).find("vertex_color("), std::string::npos);
    EXPECT_NE(frag_of(s).find("out_specular = in_color"), std::string::npos);
    EXPECT_NE(generate_scene_shaders(s, {}).material_comp.source.find("vertex_color("),
              std::string::npos);
    for (scene::Mesh& m : s.meshes)
        m.colors.clear();
    EXPECT_EQ(frag_of(s).find("vertex_color"), std::string::npos);
    EXPECT_EQ(frag_of(s).find("out_specular = in_color"), std::string::npos);
}

// A one-sided quad seen from behind shows what lies beyond it (here nothing: background), a
// double-sided one does not; the CPU's camera rays agree pixel for pixel.
TEST_F(GltfSpecTest, OneSidedQuadFromBehindShowsTheBackground) {
    for (const bool double_sided : {false, true}) {
        scene::Scene s;
        scene::Material m = test::diffuse_material(Rgb(0.5f));
        m.double_sided = double_sided;
        s.materials.push_back(m);
        // Facing +Z; the camera looks at its back from z = −2.
        s.meshes.push_back(test::make_quad(Vec3(-1, -1, 0), Vec3(2, 0, 0), Vec3(0, 2, 0), 0));
        s.camera = test::look_at(Vec3(0, 0, -2), Vec3(0.0f), 0.8f);
        const std::vector<GBufferTexel> texels = g_buffer(context(), s);
        const trace::Accel accel(s);
        int covered = 0;
        for (uint32_t y = 0; y < kRes; ++y) {
            for (uint32_t x = 0; x < kRes; ++x) {
                const scene::CameraRay r =
                    scene::generate_camera_ray(s.camera, kRes, kRes, Vec2(x + 0.5f, y + 0.5f));
                const bool cpu = bool(accel.intersect_camera({r.origin, r.direction}));
                EXPECT_EQ(texels[y * kRes + x].covered, cpu) << x << "," << y;
                covered += texels[y * kRes + x].covered ? 1 : 0;
            }
        }
        if (double_sided)
            EXPECT_GT(covered, int(kRes * kRes) / 4);
        else
            EXPECT_EQ(covered, 0);
    }
}

}  // namespace
}  // namespace mvpl::render
