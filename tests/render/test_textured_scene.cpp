// The shader chain end to end on a textured, normal-mapped, glossy scene (assets/textured, made
// by tools/make_textured_scene.py): the GPU's G-buffer resolves the material graphs with their
// textures and normal map, so the GPU image agrees with the CPU oracle (same VPLs, exact
// visibility, the same material graphs evaluated on the CPU), and with the path tracer within the
// bias that clamping explains.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>

#include "engine/core/image_metrics.h"
#include "engine/gpu/command_list.h"
#include "engine/light/light_sampler.h"
#include "engine/reference/path_tracer.h"
#include "engine/render/g_buffer_pass.h"
#include "engine/render/scene_geometry.h"
#include "engine/scene/camera.h"
#include "engine/scene/scene_loader.h"
#include "engine/trace/accel.h"
#include "engine/trace/interaction.h"
#include "engine/trace/shading_point.h"
#include "tests/gpu/gpu_test.h"
#include "tests/support/vpl_render.h"

namespace mvpl::render {
namespace {

using TexturedSceneTest = gpu::testing::GpuTest;

const char* const kScene = MVPL_ASSETS_DIR "/textured/textured.gltf";

// The G-buffer's closure and shading normal at each pixel against the CPU's at the same camera
// ray's hit (make_shading_point: the material graph and its normal map on the CPU). Pixels whose
// CPU hit is within 1e-3 of a triangle edge in uv are skipped (the rasteriser and Embree may
// then pick different triangles). Tolerance 1e-3: the interpolated uv differ by the rounding of
// the two intersection computations (~1e-6 relative), which the texture's bilinear slope (≤ 1
// per texel, 64 texels) and the normal map amplify to ~1e-4.
TEST_F(TexturedSceneTest, GBufferResolvesTexturesAndNormalMapsAsTheCpu) {
    const scene::Scene s = scene::load_scene(kScene);
    constexpr uint32_t kRes = 64;
    const SceneGeometry geometry(context(), s);
    GBufferPass pass(context(), geometry, kRes, kRes);
    context().submit_and_wait([&](gpu::CommandList& cmd) { pass.record(cmd, s.camera); });
    const std::vector<GBufferTexel> texels = pass.download();
    const trace::Accel accel(s);
    int compared = 0;
    int bad = 0;
    for (uint32_t y = 0; y < kRes; ++y) {
        for (uint32_t x = 0; x < kRes; ++x) {
            const scene::CameraRay r =
                scene::generate_camera_ray(s.camera, kRes, kRes, Vec2(x + 0.5f, y + 0.5f));
            const trace::Ray ray{r.origin, r.direction};
            const std::optional<trace::Hit> hit = accel.intersect(ray);
            const GBufferTexel& t = texels[y * kRes + x];
            if (!hit || !t.covered) continue;
            const trace::SurfaceInteraction si = trace::make_interaction(s, *hit, ray);
            if (int(t.material) != si.material) continue;  // a silhouette pixel
            const trace::ShadingPoint sp = trace::make_shading_point(accel.materials(), si);
            const material::ClosureParams& c = sp.bsdf.params();
            const material::ClosureParams expected = material::clamp_to_valid_ranges(c);
            // The G-buffer keeps the unflipped normal (the shading pass flips back faces).
            const float side =
                !si.front_face && s.materials[size_t(si.material)].double_sided ? -1.0f : 1.0f;
            const float d_base = glm::length(Vec3(t.closure.base_color - expected.base_color));
            const float d_n = glm::length(side * t.shading_normal - sp.frame.n);
            const float d_scalar = std::abs(t.closure.roughness - expected.roughness) +
                                   std::abs(t.closure.metallic - expected.metallic);
            ++compared;
            if ((d_base > 1e-3f || d_n > 1e-3f || d_scalar > 1e-3f) && bad++ < 8) {
                ADD_FAILURE() << "pixel " << x << "," << y << " material " << si.material
                              << ": base " << d_base << ", normal " << d_n << ", scalars "
                              << d_scalar;
            }
        }
    }
    EXPECT_GT(compared, int(kRes * kRes) / 2);
    EXPECT_LE(bad, compared / 200);  // edge pixels (see above)
}

// Same bound and reasoning as tests/render/test_vpl_pipeline.cpp: GPU and oracle differ only
// where the shadow cube's nearest texel decides visibility differently from Embree, at most the
// probability of that band, 1.25 · 2/res. Textures and normal maps are resolved by the same
// node evaluators (tests/gpu/test_node_eval.cpp), so they add nothing to the bound. Without the
// textures on the GPU the error must be far above it (the test can see textures).
TEST_F(TexturedSceneTest, GpuAgreesWithTheOracleWithTexturesAndNormalMaps) {
    const scene::Scene s = scene::load_scene(kScene);
    ASSERT_EQ(s.textures.size(), 3u);
    const light::VplSet vpls = test::monte_carlo_vpls(s, 48, 6, 3);
    const test::VplRenderSettings settings{.res = 64, .shadow_res = 256, .clamp = 0.05f};
    const Image oracle = test::oracle_render(s, vpls, settings);
    const Image gpu = test::gpu_render(context(), s, vpls, settings);
    const double error = compare_images(gpu, oracle).rel_mse;
    if (const char* dir = std::getenv("MVPL_TEST_IMAGES")) {  // for inspection
        write_exr(gpu, std::string(dir) + "/textured-gpu.exr");
        write_exr(oracle, std::string(dir) + "/textured-oracle.exr");
        write_png(gpu, std::string(dir) + "/textured-gpu.png");
        write_png(oracle, std::string(dir) + "/textured-oracle.png");
    }
    const double bound = 1.25 * 2.0 / 256.0;
    EXPECT_LT(error, bound);
    RecordProperty("relmse", std::to_string(error));

    scene::Scene untextured = s;
    for (scene::Material& m : untextured.materials) {
        m.base_color_texture = {};
        m.normal_texture = {};
        m.metallic_roughness_texture = {};
    }
    const double without =
        compare_images(test::gpu_render(context(), untextured, vpls, settings), oracle).rel_mse;
    EXPECT_GT(without, 4.0 * bound);
    RecordProperty("relmse_without_textures", std::to_string(without));
}

// Against the path tracer (depth 6). Clamping the geometric term at d_min biases the VPL image
// low; that bias is measured here on the oracle with the same VPLs (clamped vs unclamped image
// means) and is what the GPU may differ from the path tracer by, beyond the Monte Carlo error of
// the two estimates. That error is measured too: both estimates are means of kGroups independent
// runs (VPLs of 128 light paths each; 8 spp each), whose spread gives the standard error of the
// mean, and the tolerance is clamping bias + 3 standard errors. The emitter seen directly is
// box-filtered by the path tracer and point-sampled by the GPU, so that term is swapped as in
// test_vpl_pipeline.cpp.
//
// The swapped-in box-filtered emission is itself a Monte Carlo estimate, and a noisy one: the
// luminaire is seen nearly edge-on, about one pixel row tall at 32², yet it is 60–80 % of the
// image mean. At 16 spp its standard deviation is 3 % of the emitted term, and one estimate
// shared by all runs is an error that their spread does not show: seed 0's was +4.6 %, which
// made the GPU look 2.4–4.4 % brighter than the path tracer, although on the same camera rays
// the VPL light (unclamped) and the path tracer's agree within 1 % in total and within their
// noise at each depth 2…6. So each run gets its own estimate, and its error is part of the runs'
// spread.
TEST_F(TexturedSceneTest, GpuMatchesThePathTracerWithinTheClampingBias) {
    const scene::Scene s = scene::load_scene(kScene);
    constexpr int kRes = 32;
    // The GPU and the oracle sample pixel centres, the path tracer box-filters: pixel centres of
    // a 4× (GPU) and 2× (oracle) finer image, block-averaged, approximate the box filter (at 1×
    // the quadrature error of the sharp wall corners and the luminaire measured ±2 % of the mean,
    // changing sign with the resolution).
    constexpr int kGpuSuper = 4;
    constexpr int kOracleSuper = 2;
    constexpr float kClamp = 0.05f;
    constexpr int kGroups = 8;
    const test::VplRenderSettings clamped{
        .res = kRes * kGpuSuper, .shadow_res = 128, .clamp = kClamp};
    test::VplRenderSettings oracle_clamped_settings = clamped;
    oracle_clamped_settings.res = kRes * kOracleSuper;
    test::VplRenderSettings unclamped = oracle_clamped_settings;
    unclamped.clamp = 0.0f;
    const trace::Accel accel(s);
    const light::LightSampler lights(s);
    const reference::PathTracer tracer(s, accel, lights);
    // Depth 1 costs one camera ray per sample, so 512 spp are cheap; they keep the emitted term's
    // standard deviation per run near 0.5 % of itself (0.74 % measured at 256 spp), small next
    // to the path tracer's runs.
    reference::PathTracerOptions emitted;
    emitted.width = emitted.height = kRes;
    emitted.max_depth = 1;
    emitted.spp = 512;
    emitted.quiet = true;
    reference::PathTracerOptions p = emitted;
    p.max_depth = 6;
    p.spp = 8;

    std::vector<Rgb> gpu_runs;
    std::vector<Rgb> tracer_runs;
    Rgb oracle_clamped(0.0f);
    Rgb oracle_unclamped(0.0f);
    for (int g = 0; g < kGroups; ++g) {
        const light::VplSet vpls = test::monte_carlo_vpls(s, 128, 6, uint64_t(100 + g));
        emitted.seed = uint64_t(300 + g);
        const Rgb emitted_box = tracer.render(emitted).mean();
        // The emission term at the run's own sub-pixel positions, swapped for the box filter.
        const Rgb emitted_centres =
            test::emission_at_positions(s, vpls.vpls.size(), clamped).mean();
        gpu_runs.push_back(test::gpu_render(context(), s, vpls, clamped).mean() - emitted_centres +
                           emitted_box);
        oracle_clamped +=
            test::oracle_render(s, vpls, oracle_clamped_settings).mean() / float(kGroups);
        oracle_unclamped += test::oracle_render(s, vpls, unclamped).mean() / float(kGroups);
        p.seed = uint64_t(200 + g);
        tracer_runs.push_back(tracer.render(p).mean());
    }
    const auto mean_and_error = [](const std::vector<Rgb>& runs, int c) {
        double sum = 0.0;
        double sum2 = 0.0;
        for (const Rgb& r : runs) {
            sum += r[c];
            sum2 += double(r[c]) * r[c];
        }
        const double n = double(runs.size());
        const double mean = sum / n;
        const double variance = std::max(0.0, (sum2 - n * mean * mean) / (n - 1.0));
        return std::pair<double, double>(mean, std::sqrt(variance / n));
    };
    for (int c = 0; c < 3; ++c) {
        const auto [gpu, gpu_se] = mean_and_error(gpu_runs, c);
        const auto [reference, reference_se] = mean_and_error(tracer_runs, c);
        const double clamp_bias = std::abs(1.0 - oracle_clamped[c] / oracle_unclamped[c]);
        const double noise = std::sqrt(gpu_se * gpu_se + reference_se * reference_se) / reference;
        const double error = std::abs(1.0 - gpu / reference);
        EXPECT_LT(error, clamp_bias + 3.0 * noise) << "channel " << c;
        EXPECT_LT(noise, 0.03) << "channel " << c;  // the test still has power
        RecordProperty("clamp_bias_" + std::to_string(c), std::to_string(clamp_bias));
        RecordProperty("gpu_vs_path_tracer_" + std::to_string(c), std::to_string(error));
        std::printf(
            "channel %d: GPU %.5f, path tracer %.5f, |GPU/path tracer - 1| %.4f, clamping bias "
            "%.4f, standard error "
            "%.4f\n",
            c, gpu, reference, error, clamp_bias, noise);
    }
}

}  // namespace
}  // namespace mvpl::render
