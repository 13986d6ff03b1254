// Virtual spherical lights (issue 15, "No glossy spikes"; shaders/shared/virtual_sphere.h): over
// the glossy scene the VPL image has no spikes — the 99.9th percentile of |VPL − PT| / (PT +
// 0.01) falls with the VPL count and no pixel exceeds 10× its reference — and the GPU shades
// the spheres as the oracle does.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/image_metrics.h"
#include "engine/light/chain_options.h"
#include "engine/light/light_sampler.h"
#include "engine/light/specular_chain.h"
#include "engine/light/vpl_contribution.h"
#include "engine/reference/path_tracer.h"
#include "engine/render/shader_program.h"
#include "engine/scene/camera.h"
#include "engine/scene/scene_loader.h"
#include "engine/trace/accel.h"
#include "tests/gpu/gpu_test.h"
#include "tests/support/vpl_render.h"

namespace mvpl::render {
namespace {

using VirtualSpheresTest = gpu::testing::GpuTest;

const std::string kScene = std::string(MVPL_SOURCE_DIR) + "/assets/glossy/glossy.gltf";
constexpr int kMaxDepth = 6;

test::VplRenderSettings glossy_settings(int res) {
    test::VplRenderSettings s{.res = res, .shadow_res = 128, .clamp = light::kDefaultClamp};
    s.chain_roughness = light::kDefaultChainRoughness;  // as `mvpl render`
    s.chain_max_depth = kMaxDepth;
    s.chain_seed = 3;
    return s;
}

// The pixels whose centre the VPLs light directly: not continued by a specular chain (their error
// is the chain's, item 1 of the issue), nor next to such a pixel (the sub-pixel positions reach
// into it), nor the background.
std::vector<bool> vpl_lit_pixels(const scene::Scene& s, const trace::Accel& accel, int res,
                                 const light::ChainOptions& chains) {
    std::vector<bool> direct(size_t(res * res), false);
    for (int y = 0; y < res; ++y) {
        for (int x = 0; x < res; ++x) {
            const scene::CameraRay cr = scene::generate_camera_ray(
                s.camera, res, res, Vec2(float(x) + 0.5f, float(y) + 0.5f));
            const std::optional<light::Receiver> r =
                light::make_receiver(s, accel, trace::Ray{cr.origin, cr.direction});
            direct[size_t(y * res + x)] = r && !light::continues_chain(r->sp.bsdf, r->wo, chains);
        }
    }
    std::vector<bool> lit(direct.size(), false);
    for (int y = 1; y + 1 < res; ++y) {
        for (int x = 1; x + 1 < res; ++x) {
            bool all = true;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    all = all && direct[size_t((y + dy) * res + x + dx)];
            lit[size_t(y * res + x)] = all;
        }
    }
    return lit;
}

// compare_images' spike metrics over the masked pixels.
ImageError spikes(const Image& image, const Image& reference, const std::vector<bool>& mask) {
    Image a(int(std::count(mask.begin(), mask.end(), true)), 1);
    Image r(a.width(), 1);
    int k = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            if (!mask[size_t(y * image.width() + x)]) continue;
            a.at(k, 0) = image.at(x, y);
            r.at(k, 0) = reference.at(x, y);
            ++k;
        }
    }
    return compare_images(a, r);
}

uint64_t seed_from_env(uint64_t fallback) {
    const char* s = std::getenv("MVPL_VSL_SEED");  // to rerun the test over other seeds
    return s ? std::strtoull(s, nullptr, 10) : fallback;
}

// The spike metrics against the path tracer over the pixels the VPLs light (vpl_lit_pixels),
// computed on the oracle (the GPU shades the same VPLs alike: the next test). Counts: 64 and
// 1024 light paths at 48² (1962 such pixels: the percentile is the second-largest), the
// reference 1024 spp. 16× the paths quarter the noise's deviation; the percentile's floor is
// the bias of the clamp and the spheres (~0.55–0.8 at 1024 paths). Measured over seeds 1–10
// (MVPL_VSL_SEED): the percentile falls from 0.87–4.9 to 0.55–0.80 (by 1.14–7.5×), the largest
// ratio is 1.8–7.1 at 64 paths and 1.2–1.8 at 1024; with point VPLs at 1024 paths the
// percentile is 0.66–4.2 and the largest ratio 1.5–27.6. Over the whole image, chained pixels
// included, no pixel exceeds 10× either (issue 15's criterion): seeds 1–5 at 1024 paths, p99.9
// 0.73–0.86 and the largest ratio 1.7–2.0; without the chains' light samples (specular_chain.cpp)
// 1.03–1.10 and 6.3–6.5 (seeds 1–3). The test runs seed 1.
TEST_F(VirtualSpheresTest, NoGlossySpikes) {
    const scene::Scene s = scene::load_scene(kScene);
    const trace::Accel accel(s);
    const light::LightSampler lights(s);
    const int res = 48;
    reference::PathTracerOptions pto;
    pto.width = pto.height = res;
    pto.spp = 1024;
    pto.max_depth = kMaxDepth;
    pto.seed = 11;
    pto.quiet = true;
    const Image reference = reference::PathTracer(s, accel, lights).render(pto);
    const uint64_t seed = seed_from_env(1);
    const test::VplRenderSettings settings = glossy_settings(res);
    test::VplRenderSettings points = settings;
    points.vsl_radius = 0.0f;
    light::ChainOptions chains;
    chains.max_roughness = settings.chain_roughness;
    chains.max_depth = settings.chain_max_depth;
    const std::vector<bool> mask = vpl_lit_pixels(s, accel, res, chains);
    const ImageError low =
        spikes(test::oracle_render(s, test::monte_carlo_vpls(s, 64, kMaxDepth, seed), settings),
               reference, mask);
    const light::VplSet many = test::monte_carlo_vpls(s, 1024, kMaxDepth, seed + 100);
    const Image many_image = test::oracle_render(s, many, settings);
    const ImageError high = spikes(many_image, reference, mask);
    const ImageError whole = compare_images(many_image, reference);
    const ImageError high_points = spikes(test::oracle_render(s, many, points), reference, mask);
    std::printf("%d of %d pixels lit by VPLs\n", int(std::count(mask.begin(), mask.end(), true)),
                res * res);
    std::printf(
        "seed %llu: p99.9 %.3f (64 paths) %.3f (1024), max ratio %.2f %.2f; points: %.3f %.2f; "
        "relMSE %.4f %.4f points %.4f\n",
        (unsigned long long)seed, low.rel_err_p999, high.rel_err_p999, low.max_ratio,
        high.max_ratio, high_points.rel_err_p999, high_points.max_ratio, low.rel_mse, high.rel_mse,
        high_points.rel_mse);
    EXPECT_LT(high.rel_err_p999, low.rel_err_p999);
    EXPECT_LE(low.max_ratio, 10.0);
    EXPECT_LE(high.max_ratio, 10.0);
    std::printf("whole image at 1024 paths: p99.9 %.3f, max ratio %.2f\n", whole.rel_err_p999,
                whole.max_ratio);
    EXPECT_LE(whole.max_ratio, 10.0);
}

// GPU ≡ oracle with VSLs on the glossy scene, within the bound of the other GPU-vs-oracle tests
// (test_specular_chains.cpp): GPU and oracle differ only where the shadow cube's nearest texel
// decides visibility differently from Embree, relMSE ≤ 1.25 · 2/res; the widened lobes are the
// same arithmetic on both sides (shaders/shared/virtual_sphere.h).
TEST_F(VirtualSpheresTest, TheGpuEqualsTheOracle) {
    const scene::Scene s = scene::load_scene(kScene);
    const light::VplSet vpls = test::monte_carlo_vpls(s, 64, kMaxDepth, 5);
    test::VplRenderSettings settings = glossy_settings(40);
    settings.vsl_radius = 0.1f;  // larger than the default: most VPL–receiver pairs widened
    const Image oracle = test::oracle_render(s, vpls, settings);
    const Image gpu = test::gpu_render(context(), s, vpls, settings);
    const double bound = 1.25 * 2.0 / double(settings.shadow_res);
    const double error = compare_images(gpu, oracle).rel_mse;
    std::printf("GPU vs oracle with VSLs: relMSE %.3g (bound %.3g)\n", error, bound);
    EXPECT_LT(error, bound);
    // And the GPU shades spheres, not points: it is nearer the VSL oracle than the point VPLs'.
    test::VplRenderSettings points = settings;
    points.vsl_radius = 0.0f;
    const double to_points = compare_images(gpu, test::oracle_render(s, vpls, points)).rel_mse;
    std::printf("GPU (VSLs) vs the point VPLs' oracle: relMSE %.3g\n", to_points);
    EXPECT_GT(to_points, error);
    // A diffuse-only scene's shading program has no VSL code.
    const scene::Scene cbox =
        scene::load_scene(std::string(MVPL_SOURCE_DIR) + "/assets/cornell-box/cbox.gltf");
    const SceneShaders diffuse = generate_scene_shaders(cbox, ShaderOptions{});
    EXPECT_EQ(diffuse.shading_comp.source.find("vsl_spread2"), std::string::npos);
    EXPECT_NE(generate_scene_shaders(s, ShaderOptions{}).shading_comp.source.find("vsl_spread2"),
              std::string::npos);
}

}  // namespace
}  // namespace mvpl::render
