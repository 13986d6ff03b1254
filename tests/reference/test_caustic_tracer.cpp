// The caustic tracer (issue 15; engine/reference/caustic_tracer.h): light that reaches a diffuse
// floor through a smooth glass pane, which no VPL carries (VPLs reflect only, and the glass casts
// an opaque shadow), found by light tracing; VPL image + caustics matches the path tracer, the VPL
// image alone is dark there; a diffuse-only scene traces nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "engine/light/chain_options.h"
#include "engine/light/light_sampler.h"
#include "engine/reference/caustic_tracer.h"
#include "engine/reference/path_tracer.h"
#include "engine/reference/vpl_gather.h"
#include "engine/scene/camera.h"
#include "engine/trace/accel.h"
#include "sampler/monte_carlo_sampler.h"
#include "tests/support/sample_statistics.h"
#include "tests/support/scene_builder.h"

namespace mvpl::reference {
namespace {

constexpr int kSize = 24;
constexpr int kMaxDepth = 3;
constexpr float kPaneY = 0.5f;
constexpr float kPaneHalf = 0.5f;
constexpr float kLightHalf = 0.25f;
// The floor points that see the whole light through the pane: |x|, |z| < 2·kPaneHalf − kLightHalf
// = 0.75 (the pane halfway up); the region keeps a margin to that umbra's edge.
constexpr float kRegionHalf = 0.55f;

// A diffuse floor (y = 0) and back wall (z = −1.5) under a downward area light (0.5 × 0.5, y = 1,
// radiance 4) with a thin smooth glass pane (1 × 1, transmission 1, IOR 1.5) halfway between
// light and floor, and a point light (intensity 1) low at the side, below the pane's plane; the
// camera, below that plane too, sees the floor under the pane without looking through it. At max
// depth 3 that floor is lit through the pane (light → glass → floor → eye: the caustic tracer's),
// by the point light directly and through the wall (the VPLs').
// `glass` false: the pane is diffuse (a diffuse-only scene).
scene::Scene make_pane_scene(bool glass = true) {
    scene::Scene s;
    scene::Material pane = test::diffuse_material(Rgb(0.5f));
    if (glass) {
        pane.base_color = Rgb(1.0f);
        pane.roughness = 0.0f;
        pane.ior = 1.5f;
        pane.transmission = 1.0f;
        pane.double_sided = true;
    }
    s.materials = {test::diffuse_material(Rgb(0.8f)), test::diffuse_material(Rgb(0.0f)), pane,
                   test::diffuse_material(Rgb(0.7f))};
    s.materials[1].emissive = Rgb(4.0f);
    s.meshes.push_back(test::make_quad(Vec3(-2, 0, -1.5f), Vec3(0, 0, 3.5f), Vec3(4, 0, 0), 0));
    s.meshes.push_back(test::make_quad(Vec3(-2, 0, -1.5f), Vec3(4, 0, 0), Vec3(0, 2, 0), 3));
    const float l = kLightHalf, h = kPaneHalf;
    s.meshes.push_back(  // facing down
        test::make_quad(Vec3(-l, 1.0f, -l), Vec3(2 * l, 0, 0), Vec3(0, 0, 2 * l), 1));
    s.meshes.push_back(
        test::make_quad(Vec3(-h, kPaneY, -h), Vec3(2 * h, 0, 0), Vec3(0, 0, 2 * h), 2));
    scene::Light point;
    point.position = Vec3(1.2f, 0.3f, 0.0f);
    point.intensity = Rgb(1.0f);
    s.lights.push_back(point);
    s.camera = test::look_at(Vec3(0.0f, 0.45f, 1.4f), Vec3(0.0f, 0.0f, -0.1f), 1.0f);
    s.has_camera = true;
    return s;
}

// Whether pixel (x, y)'s centre ray meets the floor inside the region under the pane (the camera
// is below the pane's plane, so the ray does not cross it).
bool under_pane(const scene::Camera& camera, int x, int y) {
    const scene::CameraRay cr =
        scene::generate_camera_ray(camera, kSize, kSize, Vec2(float(x) + 0.5f, float(y) + 0.5f));
    if (!(cr.direction.y < 0.0f)) return false;
    const Vec3 p = cr.origin - (cr.origin.y / cr.direction.y) * cr.direction;
    return std::abs(p.x) < kRegionHalf && std::abs(p.z) < kRegionHalf;
}

double region_mean(const scene::Camera& camera, const Image& image) {
    double sum = 0.0;
    int n = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            if (!under_pane(camera, x, y)) continue;
            sum += luminance(image.at(x, y));
            ++n;
        }
    }
    EXPECT_GE(n, 40) << "the region under the pane should cover many pixels";
    return sum / std::max(n, 1);
}

// Unbiased against the path tracer: over kRuns independent seeds, the region's mean of
// (VPL oracle + caustics) and of the path tracer agree within 4σ, σ² the sum of both means'
// variances estimated from the runs' spread (|t| > 4 with probability < 0.2 % at ≈ 14 degrees
// of freedom; the seeds are fixed, so the test is deterministic). The oracle is unclamped with
// point VPLs and the chains on (the renderer's partition: path_partition.h), its light tracer
// leaving no VPL on the glass. Without the caustics the region has only the point light's and
// the wall's light: less than half the path tracer's (about a fifth: printed).
TEST(CausticTracer, FloorUnderAGlassPaneMatchesThePathTracer) {
    const scene::Scene s = make_pane_scene();
    const trace::Accel accel(s);
    const light::LightSampler lights(s);
    light::ChainOptions chains;
    chains.max_roughness = light::kDefaultChainRoughness;
    chains.max_depth = kMaxDepth;
    constexpr int kRuns = 8;
    std::vector<double> sum, tracer, vpl_only;
    for (int run = 0; run < kRuns; ++run) {
        const uint64_t seed = uint64_t(run + 1);
        sampler::MonteCarloOptions mc;
        mc.paths = 512;
        mc.seed = seed;
        mc.tracer.max_depth = kMaxDepth;
        mc.tracer.specular = chains;
        const light::VplSet vpls = sampler::MonteCarloSampler(s, accel, lights).generate(mc);
        GatherOptions g;
        g.width = g.height = kSize;
        g.clamp = 0.0f;
        g.vsl_radius = 0.0f;
        g.max_depth = kMaxDepth;
        g.chains = chains;
        g.chain_seed = seed;
        const double vpl = region_mean(s.camera, gather_vpls(s, accel, vpls, g));
        CausticOptions c;
        c.width = c.height = kSize;
        c.max_depth = kMaxDepth;
        c.specular = chains;
        c.seed = seed;
        c.paths_per_pass = 8192;
        CausticTracer caustics(s, accel, lights, c);
        ASSERT_TRUE(caustics.active());
        for (int pass = 0; pass < 4; ++pass)
            caustics.add_pass();
        const double caustic = region_mean(s.camera, caustics.image());
        PathTracerOptions o;
        o.width = o.height = kSize;
        o.spp = 128;
        o.max_depth = kMaxDepth;
        o.seed = seed;
        o.quiet = true;
        tracer.push_back(region_mean(s.camera, PathTracer(s, accel, lights).render(o)));
        sum.push_back(vpl + caustic);
        vpl_only.push_back(vpl);
    }
    const test::MeanAndError a = test::mean_and_error(sum);
    const test::MeanAndError b = test::mean_and_error(tracer);
    const test::MeanAndError v = test::mean_and_error(vpl_only);
    const double sigma = std::hypot(a.standard_error, b.standard_error);
    std::printf(
        "floor under the pane: VPLs + caustics %.5f (±%.5f), path tracer %.5f (±%.5f), "
        "VPLs alone %.5f\n",
        a.mean, a.standard_error, b.mean, b.standard_error, v.mean);
    EXPECT_LT(std::abs(a.mean - b.mean), 4.0 * sigma);
    EXPECT_GT(b.mean, 0.05);
    EXPECT_LT(v.mean, 0.5 * b.mean) << "without caustics the floor under the pane should be dark";
}

// Leave out what a scene does not need: with a diffuse pane nothing can leave the VPLs' share,
// so the tracer is inactive and a pass traces no ray; max depth 2 (direct light only) neither.
TEST(CausticTracer, ADiffuseSceneTracesNoRays) {
    const scene::Scene s = make_pane_scene(false);
    const trace::Accel accel(s);
    const light::LightSampler lights(s);
    CausticOptions c;
    c.width = c.height = kSize;
    c.specular.max_roughness = light::kDefaultChainRoughness;
    CausticTracer caustics(s, accel, lights, c);
    EXPECT_FALSE(caustics.active());
    const uint64_t before = accel.ray_count();
    caustics.add_pass();
    EXPECT_EQ(accel.ray_count(), before);
    EXPECT_EQ(caustics.passes(), 1u);
    const Image image = caustics.image();
    for (const Rgb& p : image.pixels())
        EXPECT_TRUE(is_black(p));

    const scene::Scene glass = make_pane_scene(true);
    const trace::Accel glass_accel(glass);
    const light::LightSampler glass_lights(glass);
    EXPECT_TRUE(CausticTracer(glass, glass_accel, glass_lights, c).active());
    c.max_depth = 2;
    EXPECT_FALSE(CausticTracer(glass, glass_accel, glass_lights, c).active());
}

}  // namespace
}  // namespace mvpl::reference
