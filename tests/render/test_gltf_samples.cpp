// The Khronos sample models of ../shared/gltf-samples (beside a checkout in this workplace) that
// test glTF features (issue 12), rendered by the path tracer and the GPU VPL renderer. Each test
// skips when the samples are not there (they are not part of the repository).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <optional>
#include <string>

#include "engine/gpu/command_list.h"
#include "engine/light/light_sampler.h"
#include "engine/material/graph_eval.h"
#include "engine/reference/path_tracer.h"
#include "engine/render/g_buffer_pass.h"
#include "engine/render/scene_geometry.h"
#include "engine/scene/camera.h"
#include "engine/scene/scene_loader.h"
#include "engine/trace/accel.h"
#include "engine/trace/interaction.h"
#include "engine/trace/shading_point.h"
#include "tests/gpu/gpu_test.h"
#include "tests/support/scene_builder.h"
#include "tests/support/vpl_render.h"

namespace mvpl {
namespace {

using GltfSamplesTest = gpu::testing::GpuTest;

std::optional<scene::Scene> load_sample(const std::string& name) {
    const std::string path =
        MVPL_SOURCE_DIR "/../shared/gltf-samples/" + name + "/glTF/" + name + ".gltf";
    if (!std::filesystem::exists(path)) return std::nullopt;
    return scene::load_scene(path);
}

// VertexColorTest lit head-on by a directional light (it has none) and seen head-on, without its
// label plane (whose text is not under test and would shadow nothing but clutter the view).
scene::Scene vertex_color_setup(scene::Scene s) {
    std::erase_if(s.meshes, [&](const scene::Mesh& m) {
        return s.materials[size_t(m.material)].name == "Label_Mat";
    });
    s.camera = test::look_at(Vec3(0, 0, 3), Vec3(0.0f), 0.75f);
    scene::Light sun;
    sun.type = scene::LightType::Directional;
    sun.intensity = Rgb(3.0f);
    sun.direction = Vec3(0, 0, -1);
    s.lights = {sun};
    return s;
}

// The model's README: the top ("test") row's red, green and blue checks, multiplied by red,
// green and blue COLOR_0, look as the bottom ("pass") row's, which are multiplied by white; a
// renderer that ignores COLOR_0 shows a cyan, magenta or yellow X over each test check. The
// check quads (from the file's accessors): each 0.462 wide, from x = −0.779, −0.231 and 0.361;
// the test row's y ∈ [0.109, 0.572], the pass row's 0.868 lower.
struct CheckMeans {
    std::array<DVec3, 3> test{};
    std::array<DVec3, 3> pass{};
    std::array<int, 3> test_count{};
    std::array<int, 3> pass_count{};
};

CheckMeans check_means(const scene::Scene& s, const Image& image) {
    const trace::Accel accel(s);
    constexpr float kLeft[3] = {-0.779f, -0.231f, 0.361f};
    constexpr float kWidth = 0.462f;
    constexpr float kInset = 0.03f;  // away from the quads' edges (anti-aliased pixels)
    CheckMeans m;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const scene::CameraRay r = scene::generate_camera_ray(
                s.camera, image.width(), image.height(), Vec2(x + 0.5f, y + 0.5f));
            const auto hit = accel.intersect_camera({r.origin, r.direction});
            if (!hit) continue;
            const Vec3 p = r.origin + hit->t * r.direction;
            for (int k = 0; k < 3; ++k) {
                if (p.x < kLeft[k] + kInset || p.x > kLeft[k] + kWidth - kInset) continue;
                const Rgb& c = image.at(x, y);
                if (p.y > 0.109f + kInset && p.y < 0.572f - kInset) {
                    m.test[size_t(k)] += DVec3(c);
                    ++m.test_count[size_t(k)];
                } else if (p.y > 0.109f - 0.868f + kInset && p.y < 0.572f - 0.868f - kInset) {
                    m.pass[size_t(k)] += DVec3(c);
                    ++m.pass_count[size_t(k)];
                }
            }
        }
    }
    for (int k = 0; k < 3; ++k) {
        m.test[size_t(k)] /= double(std::max(m.test_count[size_t(k)], 1));
        m.pass[size_t(k)] /= double(std::max(m.pass_count[size_t(k)], 1));
    }
    return m;
}

// The largest difference between a test check's mean colour and its pass check's, in the
// channels other than the check's own (red, green, blue for checks 0, 1, 2), relative to the
// pass check's own channel: where COLOR_0 is applied those channels are the grey background in
// both rows; where it is not, the test row's X shows in them. The check's own channel differs
// by the drawing of the two rows' textures (measured 5–7 %), bounded at 10 %.
double off_channel_difference(const scene::Scene& s, const Image& image, const char* renderer) {
    const CheckMeans m = check_means(s, image);
    double worst = 0.0;
    for (int k = 0; k < 3; ++k) {
        EXPECT_GT(m.test_count[size_t(k)], 50) << renderer;
        EXPECT_GT(m.pass_count[size_t(k)], 50) << renderer;
        const DVec3 test = m.test[size_t(k)];
        const DVec3 pass = m.pass[size_t(k)];
        const double own = pass[k];
        EXPECT_GT(own, 0.05) << renderer << ": check " << k << " is dark";
        EXPECT_NEAR(test[k], own, 0.10 * own) << renderer << ": check " << k;
        for (int c = 0; c < 3; ++c) {
            if (c != k) worst = std::max(worst, std::abs(test[c] - pass[c]) / own);
        }
    }
    return worst;
}

TEST_F(GltfSamplesTest, VertexColorTestRowsAgreeInBothRenderers) {
    const std::optional<scene::Scene> loaded = load_sample("VertexColorTest");
    if (!loaded) GTEST_SKIP() << "../shared/gltf-samples is not beside this checkout";
    const scene::Scene s = vertex_color_setup(*loaded);

    const trace::Accel accel(s);
    const light::LightSampler lights(s);
    reference::PathTracerOptions o;
    o.width = o.height = 96;
    o.spp = 4;
    o.max_depth = 2;  // direct light: the directional light's next-event estimate, no noise
    o.quiet = true;
    const double pt =
        off_channel_difference(s, reference::PathTracer(s, accel, lights).render(o), "path tracer");
    EXPECT_LT(pt, 0.03) << "path tracer";

    test::VplRenderSettings settings;
    settings.res = 96;
    const light::VplSet vpls = test::monte_carlo_vpls(s, 4, 2, 1);
    const double gpu =
        off_channel_difference(s, test::gpu_render(context(), s, vpls, settings), "GPU");
    EXPECT_LT(gpu, 0.03) << "GPU";

    // The bound sees a renderer that ignores COLOR_0: the same scene without it shows the X.
    scene::Scene plain = s;
    for (scene::Mesh& mesh : plain.meshes)
        mesh.colors.clear();
    const trace::Accel plain_accel(plain);
    const light::LightSampler plain_lights(plain);
    const double ignored = off_channel_difference(
        plain, reference::PathTracer(plain, plain_accel, plain_lights).render(o), "no COLOR_0");
    EXPECT_GT(ignored, 0.1);
    RecordProperty("path_tracer", std::to_string(pt));
    RecordProperty("gpu", std::to_string(gpu));
    RecordProperty("without_color_0", std::to_string(ignored));
}

// AlphaBlendModeTest, seen by its framing camera: wherever the camera ray meets a masked panel
// (MatCutoff25, MatCutoff75, MatCutoffDefault) at a texel whose alpha is clearly below the
// panel's cutoff (by 0.05: filtering and rounding aside), the CPU's camera ray and the
// G-buffer show what lies behind it; where it is clearly above, they show the panel.
TEST_F(GltfSamplesTest, AlphaBlendModeTestMaskedTexelsShowWhatLiesBehind) {
    const std::optional<scene::Scene> loaded = load_sample("AlphaBlendModeTest");
    if (!loaded) GTEST_SKIP() << "../shared/gltf-samples is not beside this checkout";
    const scene::Scene& s = *loaded;
    scene::Scene opaque = s;  // the panels uncut: where the camera ray meets them
    for (scene::Material& m : opaque.materials)
        m.alpha_mode = scene::AlphaMode::Opaque;
    const trace::Accel accel(s);
    const trace::Accel opaque_accel(opaque);
    constexpr uint32_t kRes = 96;
    const render::SceneGeometry geometry(context(), s);
    render::GBufferPass pass(context(), geometry, kRes, kRes);
    context().submit_and_wait([&](gpu::CommandList& cmd) { pass.record(cmd, s.camera); });
    const std::vector<render::GBufferTexel> texels = pass.download();
    int cut = 0;
    int kept = 0;
    int gpu_wrong = 0;
    for (uint32_t y = 0; y < kRes; ++y) {
        for (uint32_t x = 0; x < kRes; ++x) {
            const scene::CameraRay r =
                scene::generate_camera_ray(s.camera, kRes, kRes, Vec2(x + 0.5f, y + 0.5f));
            const trace::Ray ray{r.origin, r.direction};
            const auto panel = opaque_accel.intersect_camera(ray);
            if (!panel) continue;
            const int material = s.meshes[size_t(panel->mesh)].material;
            if (!accel.materials().masked(material)) continue;
            const material::MaterialGraph& g = accel.materials().graph(material);
            const float alpha = material::evaluate_input(
                                    g, g.alpha, s.textures,
                                    trace::surface_attributes(s.meshes[size_t(panel->mesh)],
                                                              panel->triangle, panel->barycentric))
                                    .x;
            if (std::abs(alpha - g.alpha_cutoff) < 0.05f) continue;
            const auto hit = accel.intersect_camera(ray);
            const render::GBufferTexel& t = texels[y * kRes + x];
            const Vec3 at_panel = r.origin + panel->t * r.direction;
            // The G-buffer's surface is the panel's where it lies on it (within 1e-3 of the
            // panel's distance), beyond it otherwise (or nothing).
            const bool gpu_on_panel =
                t.covered && glm::length(t.position - at_panel) < 1e-3f * panel->t;
            if (alpha < g.alpha_cutoff) {
                ++cut;
                EXPECT_TRUE(!hit || hit->t > panel->t * 1.0001f) << x << "," << y;
                gpu_wrong += gpu_on_panel ? 1 : 0;
            } else {
                ++kept;
                EXPECT_TRUE(hit && hit->mesh == panel->mesh && hit->t == panel->t) << x << "," << y;
                gpu_wrong += gpu_on_panel ? 0 : 1;
            }
        }
    }
    EXPECT_GT(cut, 20);
    EXPECT_GT(kept, 20);
    // Pixels on the edge of a cut region may rasterise either way: at most 2 %.
    EXPECT_LE(gpu_wrong, (cut + kept) / 50);
    RecordProperty("cut", cut);
    RecordProperty("kept", kept);
    RecordProperty("gpu_wrong", gpu_wrong);
}

// TextureSettingsTest seen head-on (+Z, framing its bounds): every failure of its cells is a red
// mark — the single-sided cell's comes through a back face that the camera must not see, the
// others from wrong wrap modes. No base colour the camera sees is red (r > 0.5 with g and b
// below 0.25); with the back face seen the single-sided cell's red X shows.
int red_texels_seen(const scene::Scene& s, const trace::Accel& accel) {
    int red = 0;
    constexpr int kRes = 128;
    for (int y = 0; y < kRes; ++y) {
        for (int x = 0; x < kRes; ++x) {
            const scene::CameraRay r =
                scene::generate_camera_ray(s.camera, kRes, kRes, Vec2(x + 0.5f, y + 0.5f));
            const trace::Ray ray{r.origin, r.direction};
            const auto hit = accel.intersect_camera(ray);
            if (!hit) continue;
            const Rgb c =
                trace::make_shading_point(accel.materials(), trace::make_interaction(s, *hit, ray))
                    .bsdf.params()
                    .base_color;
            red += c.r > 0.5f && c.g < 0.25f && c.b < 0.25f ? 1 : 0;
        }
    }
    return red;
}

TEST(GltfSamples, TextureSettingsTestShowsNoRedMark) {
    std::optional<scene::Scene> s = load_sample("TextureSettingsTest");
    if (!s) GTEST_SKIP() << "../shared/gltf-samples is not beside this checkout";
    const scene::Bounds b = s->bounds();
    const Vec3 centre = b.center();
    const float half = 0.5f * std::max(b.hi.x - b.lo.x, b.hi.y - b.lo.y);
    s->camera = test::look_at(centre + Vec3(0, 0, 3.0f * half), centre, 0.7f);
    const trace::Accel accel(*s);
    EXPECT_EQ(red_texels_seen(*s, accel), 0);
    // The single-sided cell seen from behind (its material made double-sided) shows red.
    scene::Scene seen = *s;
    for (scene::Material& m : seen.materials) {
        if (m.name == "SingleSidedMaterial") m.double_sided = true;
    }
    const trace::Accel seen_accel(seen);
    const int red = red_texels_seen(seen, seen_accel);
    EXPECT_GT(red, 10);  // measured 22 at 128²
    RecordProperty("red_with_back_face", red);
}

// BoxVertexColors: a grey (0.8) material whose COLOR_0 paints the cube's corners; its base
// colour at the camera's hits (the file's framing) is far from grey somewhere.
TEST(GltfSamples, BoxVertexColorsIsNotUniformGrey) {
    const std::optional<scene::Scene> s = load_sample("BoxVertexColors");
    if (!s) GTEST_SKIP() << "../shared/gltf-samples is not beside this checkout";
    const trace::Accel accel(*s);
    float chroma = 0.0f;
    int hits = 0;
    constexpr int kRes = 32;
    for (int y = 0; y < kRes; ++y) {
        for (int x = 0; x < kRes; ++x) {
            const scene::CameraRay r =
                scene::generate_camera_ray(s->camera, kRes, kRes, Vec2(x + 0.5f, y + 0.5f));
            const trace::Ray ray{r.origin, r.direction};
            const auto hit = accel.intersect_camera(ray);
            if (!hit) continue;
            ++hits;
            const Rgb c =
                trace::make_shading_point(accel.materials(), trace::make_interaction(*s, *hit, ray))
                    .bsdf.params()
                    .base_color;
            chroma = std::max(chroma, max_component(c) - std::min({c.r, c.g, c.b}));
        }
    }
    EXPECT_GT(hits, kRes * kRes / 10);
    EXPECT_GT(chroma, 0.3f);
}

}  // namespace
}  // namespace mvpl
