// Camera paths continued through glossy surfaces (light/specular_chain.h, issue 15), in the CPU
// oracle: a mirror sphere under a uniform sky against its closed form, and a mirror sphere in a
// coloured box against the path tracer — which the oracle without chains misses by far (a
// point VPL cannot light a near-mirror).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "engine/core/image.h"
#include "engine/core/subpixel.h"
#include "engine/light/light_sampler.h"
#include "engine/light/specular_chain.h"
#include "engine/material/fresnel.h"
#include "engine/reference/path_tracer.h"
#include "engine/reference/vpl_gather.h"
#include "engine/sampler/monte_carlo_sampler.h"
#include "engine/scene/camera.h"
#include "engine/trace/accel.h"
#include "tests/support/mirror_box.h"
#include "tests/support/oracle_against_tracer.h"
#include "tests/support/sample_statistics.h"
#include "tests/support/scene_builder.h"

namespace mvpl::reference {
namespace {

const Rgb kSky(0.8f, 1.0f, 1.3f);
const Rgb kGold(1.0f, 0.78f, 0.34f);
constexpr float kSphereRadius = 0.5f;

scene::Material mirror(const Rgb& f0) {
    scene::Material m;
    m.base_color = f0;
    m.metallic = 1.0f;
    m.roughness = 0.0f;
    return m;
}

// Where the camera ray through the centre of pixel (x, y) meets the sphere of radius r at the
// origin: its unit normal there, if it does.
std::optional<Vec3> sphere_normal(const scene::Camera& camera, int size, int x, int y, float r) {
    const scene::CameraRay cr =
        scene::generate_camera_ray(camera, size, size, Vec2(float(x) + 0.5f, float(y) + 0.5f));
    const float b = glm::dot(cr.origin, cr.direction);
    const float c = glm::dot(cr.origin, cr.origin) - r * r;
    const float disc = b * b - c;
    if (disc <= 0.0f) return std::nullopt;
    return glm::normalize(cr.origin + (-b - std::sqrt(disc)) * cr.direction);
}

// Mean luminance over the pixels whose centre ray meets the sphere at cos θ ≥ 0.3.
double sphere_pixels_mean(const scene::Scene& s, const Image& image, int size) {
    double sum = 0.0;
    int n = 0;
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const auto normal = sphere_normal(s.camera, size, x, y, kSphereRadius);
            if (!normal) continue;
            const Vec3 to_eye = glm::normalize(s.camera.position() - *normal * kSphereRadius);
            if (glm::dot(*normal, to_eye) < 0.3f) continue;
            sum += luminance(image.at(x, y));
            ++n;
        }
    }
    return sum / std::max(n, 1);
}

// The mirror box with a roughness-0.15 sphere (chained at the bound 0.2) and a point light
// beside the camera, whose highlight on the sphere is smaller than a pixel at these sizes.
scene::Scene glossy_box_with_point_light() {
    scene::Scene s = test::make_mirror_box();
    s.materials[3].roughness = 0.15f;
    scene::Light point;
    point.type = scene::LightType::Point;
    point.position = Vec3(0.6f, 0.5f, 0.9f);
    point.intensity = Rgb(3.0f);
    s.lights.push_back(point);
    return s;
}

GatherOptions chain_gather(int size, int max_depth, float max_roughness) {
    GatherOptions g;
    g.width = g.height = size;
    g.clamp = 0.0f;
    g.vsl_radius = 0.0f;  // point VPLs: unbiased (virtual spheres blur glossy lobes)
    g.max_depth = max_depth;
    g.chains.max_roughness = max_roughness;
    g.chains.max_depth = max_depth;
    return g;
}

// Under a uniform sky L a mirror of reflectance F reflects F(cos θ)·L. The GGX sample of a
// roughness-0 conductor (α = 10⁻⁴) has weight F(v·h)·G₂/G₁ with h within 10⁻⁴ rad of n, and
// G₂/G₁ = 1 − O(α² tan² θ): at cos θ ≥ 0.3 below 10⁻⁶. Per pixel within 0.5 % (the facets of a
// level-5 icosphere tilt the interpolated normal by < 1.5 mrad from the analytic one: a change of
// cos θ by < 1.5 · 10⁻³, of F by < 0.4 %).
TEST(SpecularChain, AMirrorSphereUnderTheSkyReflectsFresnelTimesTheSky) {
    constexpr int kSize = 24;
    scene::Scene s;
    s.materials = {mirror(kGold)};
    s.meshes.push_back(test::make_icosphere(Vec3(0.0f), kSphereRadius, 5, false, 0));
    s.camera = test::look_at(Vec3(0.0f, 0.0f, 3.0f), Vec3(0.0f), 0.3f);
    s.has_camera = true;
    s.environment.radiance = kSky;
    const trace::Accel accel(s);
    GatherOptions g = chain_gather(kSize, -1, 0.1f);
    g.subpixel = SubpixelSchedule{false, 32};  // pixel centres, as sphere_normal
    const Image image = gather_vpls(s, accel, light::VplSet{}, g);
    const Image plain = gather_vpls(s, accel, light::VplSet{}, chain_gather(kSize, -1, -1.0f));
    int checked = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const auto n = sphere_normal(s.camera, kSize, x, y, kSphereRadius);
            if (!n) continue;
            const Vec3 to_eye = glm::normalize(s.camera.position() - *n * kSphereRadius);
            const float cos_theta = glm::dot(*n, to_eye);
            if (cos_theta < 0.3f) continue;  // the silhouette: facets and pixel coverage
            const Rgb expected = material::fresnel_schlick(kGold, Rgb(1.0f), cos_theta) * kSky;
            const Rgb got = image.at(x, y);
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(got[c] / expected[c], 1.0f, 5e-3f) << x << "," << y << " c" << c;
            }
            // Without chains the mirror is black (no VPL, nothing seen directly but the sky).
            EXPECT_EQ(plain.at(x, y), Rgb(0.0f));
            ++checked;
        }
    }
    EXPECT_GT(checked, kSize * kSize / 3);
}

// A coloured box lit by an area light in its ceiling, a mirror sphere in it: the sphere shows
// the walls, lit by VPLs at the chain's first rough vertex. Both the oracle (Monte Carlo VPLs,
// no clamping) and the path tracer are unbiased, so their means over the sphere's pixels agree
// within their noise; the bound is 4σ of the difference, σ² the sum of both estimates' variances
// measured over independent seeds (kRuns each): the ratio is then about Student-t distributed
// with ≈ 6 degrees of freedom, |t| > 4 with probability 0.7 % (the seeds are fixed, so the test is
// deterministic). The oracle without chains is black on the
// mirror but for rare sparkles: far outside that bound.
//
// Max depth 3: the walls seen in the mirror lit by the emitter's VPLs. From depth 4 on the
// sphere also shows the caustic it throws on the ceiling around the light (light → mirror →
// ceiling), which a VPL on the mirror delivers only when the receiver lies within 10⁻⁴ rad of
// its reflected direction: at 8192 paths and depth 6 the oracle's sphere was 4.6 % below the
// path tracer's, converged (the same at 32768). That is the glossy VPL term of issue 15's item 2
// (virtual spherical lights), not the chain.
TEST(SpecularChain, AMirrorSphereInAColouredBoxMatchesThePathTracer) {
    const scene::Scene s = test::make_mirror_box();
    test::OracleAgainstTracer setup;
    setup.max_depth = 3;
    setup.chain_roughness = 0.1f;
    const test::OracleTracerMeans m = test::compare_oracle_with_tracer(
        s, setup, [&](const Image& image) { return sphere_pixels_mean(s, image, setup.size); });
    const double sigma = m.sigma();
    RecordProperty("vpl_over_pt", std::to_string(m.oracle.mean / m.tracer.mean));
    std::printf("sphere: oracle %.5f, path tracer %.5f, sigma %.5f, oracle without chains %.5f\n",
                m.oracle.mean, m.tracer.mean, sigma, m.without_chains);
    EXPECT_LT(std::abs(m.oracle.mean - m.tracer.mean), 4.0 * sigma)
        << "oracle " << m.oracle.mean << ", path tracer " << m.tracer.mean << ", sigma " << sigma;
    EXPECT_GT(m.tracer.mean, 0.05);
    EXPECT_LT(m.without_chains, 0.5 * m.tracer.mean)
        << "without chains the mirror should be nearly black";
}

// A BSDF sample never finds a punctual light, and a chained vertex is not lit by VPLs: the
// chain must add the point light's reflection at its glossy vertices itself (specular_chain.cpp,
// punctual_light). Max depth 2, so the sphere shows direct light only: the area light it
// reflects (found by the chain's BSDF samples) and the point light's highlight on a roughness
// 0.15 gold sphere (chained at the bound 0.2). Measured: oracle 0.4209, path tracer 0.4051,
// σ 0.0051 (0.4191, σ 0.0048 before the chains' light samples); without the point light's term the
// oracle's sphere loses the highlight (0.1516, 55σ below).
TEST(SpecularChain, AGlossySphereReflectsAPointLight) {
    const scene::Scene s = glossy_box_with_point_light();
    test::OracleAgainstTracer setup;
    setup.max_depth = 2;
    // 64 sub-pixel positions, rotated per run: the highlights are smaller than a pixel, and the
    // runs' spread must see the quadrature's error over the pixel as well.
    setup.paths = 2048;
    setup.rotate_subpixel = true;
    const test::OracleTracerMeans m = test::compare_oracle_with_tracer(
        s, setup, [&](const Image& image) { return sphere_pixels_mean(s, image, setup.size); });
    const double sigma = m.sigma();
    std::printf("glossy sphere, point light: oracle %.5f, path tracer %.5f, sigma %.5f\n",
                m.oracle.mean, m.tracer.mean, sigma);
    // 4σ of the difference of two independent means (as the mirror test above).
    EXPECT_LT(std::abs(m.oracle.mean - m.tracer.mean), 4.0 * sigma)
        << "oracle " << m.oracle.mean << ", path tracer " << m.tracer.mean << ", sigma " << sigma;
    EXPECT_GT(m.tracer.mean, 0.02);
}

// A small area light in a glossy mirror (roughness 0.15, α = 0.0225: the reflected lobe about
// 0.09 rad wide, the light 0.05 m across at ~1.5 m, 0.03 rad) is a target that the chain's BSDF
// samples find rarely; its light samples, weighted against them by the power heuristic
// (specular_chain.cpp, sampled_light), find it at every vertex. Both estimators of the light the
// sphere reflects are unbiased, so their means over 96 runs agree within 4σ of the difference,
// and the light samples must cut the run-to-run variance of the sphere's mean by at least 4×
// (measured over 960 runs: 0.0678 and 0.0616, variances 0.0030 and 0.058, 19×; a light 0.02 m
// across was never hit by 670 000 BSDF samples). On assets/glossy one pixel of the gold sphere
// read 0.02 or 40 times the path tracer without them.
TEST(SpecularChain, LightSamplesFindASmallAreaLightInAGlossyMirror) {
    scene::Scene s = test::make_mirror_box();
    constexpr float kSide = 0.05f;  // the box's light is 0.6 m across: the same power
    s.materials[3].roughness = 0.15f;
    s.materials[4].emissive = Rgb(8.0f * (0.6f / kSide) * (0.6f / kSide));
    s.meshes[5] = test::make_quad(Vec3(-0.5f * kSide, 0.99f, -0.5f * kSide), Vec3(kSide, 0, 0),
                                  Vec3(0, 0, kSide), 4);
    const trace::Accel accel(s);
    const light::LightSampler lights(s);
    light::ChainOptions options;
    options.max_roughness = light::kDefaultChainRoughness;
    options.max_depth = 2;  // direct light only: what the chain meets is all it adds
    constexpr int kSize = 32, kRuns = 96;
    struct Stats {
        double sum = 0.0, sum2 = 0.0;
        void add(double v) {
            sum += v;
            sum2 += v * v;
        }
        double mean() const { return sum / kRuns; }
        double variance() const { return (sum2 - sum * sum / kRuns) / (kRuns - 1); }
    };
    Stats with, without;
    for (int run = 0; run < kRuns; ++run) {
        double a = 0.0, b = 0.0;
        int n = 0;
        for (int y = 0; y < kSize; ++y) {
            for (int x = 0; x < kSize; ++x) {
                if (!sphere_normal(s.camera, kSize, x, y, test::kMirrorSphereRadius)) continue;
                const scene::CameraRay cr = scene::generate_camera_ray(
                    s.camera, kSize, kSize, Vec2(float(x) + 0.5f, float(y) + 0.5f));
                const trace::Ray ray{cr.origin, cr.direction};
                const uint64_t pixel = uint64_t(y * kSize + x);
                Rng ra = light::chain_rng(uint64_t(run), pixel, 0);
                Rng rb = light::chain_rng(uint64_t(run), pixel, 0);
                a += luminance(
                    light::make_chained_receiver(s, accel, ray, ra, options, nullptr, &lights)
                        .chain_emitted);
                b += luminance(
                    light::make_chained_receiver(s, accel, ray, rb, options).chain_emitted);
                ++n;
            }
        }
        ASSERT_GT(n, 100);
        with.add(a / n);
        without.add(b / n);
    }
    const double sigma = std::sqrt((with.variance() + without.variance()) / kRuns);
    std::printf(
        "small light in a glossy mirror: with light samples %.5f (var %.3g), BSDF samples "
        "alone %.5f (var %.3g)\n",
        with.mean(), with.variance(), without.mean(), without.variance());
    EXPECT_GT(with.mean(), 0.01);
    EXPECT_LT(std::abs(with.mean() - without.mean()), 4.0 * sigma);
    EXPECT_LT(with.variance(), 0.25 * without.variance());
}

// A point light's highlight on a glossy sphere (roughness 0.15) is smaller than a pixel: the
// chain of one sub-pixel position hits it or not, and the pixel's light jumps between 0 and many
// times its mean. pixel_chain_emission's extra samples (ChainOptions::emission_samples)
// integrate the pixel better without bias: over 96 runs at one position per pixel, the sphere's
// mean with 8 samples equals that with 1 within 4σ of the difference, and its run-to-run
// variance falls by at least 3× (measured 9.4×; 10× at roughness 0.1). At roughness 0.05 the
// highlight's tail is too heavy for 96 runs to estimate either variance (the one-sample runs
// missed the rare brightest hits that the eight-sample runs caught).
TEST(SpecularChain, MoreSubPixelSamplesIntegrateAHighlightWithoutBias) {
    const scene::Scene s = glossy_box_with_point_light();
    const trace::Accel accel(s);
    const light::LightSampler lights(s);
    light::ChainOptions one;
    one.max_roughness = light::kDefaultChainRoughness;
    one.max_depth = 2;
    light::ChainOptions eight = one;
    eight.emission_samples = 8;
    constexpr int kSize = 24, kRuns = 96;
    std::vector<double> a, b;
    for (int run = 0; run < kRuns; ++run) {
        double sum_one = 0.0, sum_eight = 0.0;
        int n = 0;
        for (int y = 0; y < kSize; ++y) {
            for (int x = 0; x < kSize; ++x) {
                if (!sphere_normal(s.camera, kSize, x, y, test::kMirrorSphereRadius)) continue;
                Rng rng = light::chain_rng(uint64_t(run), uint64_t(y * kSize + x), 0);
                const Vec2 offset(rng.next_float(), rng.next_float());
                const scene::CameraRay cr = scene::generate_camera_ray(
                    s.camera, kSize, kSize, Vec2(float(x) + offset.x, float(y) + offset.y));
                const trace::Ray ray{cr.origin, cr.direction};
                const light::ChainedReceiver first =
                    light::make_chained_receiver(s, accel, ray, rng, one, nullptr, &lights);
                sum_one += luminance(first.chain_emitted);
                const bool centre =
                    light::pixel_centre_continues(s, accel, s.camera, kSize, kSize, x, y, eight);
                sum_eight += luminance(light::pixel_chain_emission(
                    s, accel, s.camera, kSize, kSize, x, y, centre, first, rng, eight, &lights));
                ++n;
            }
        }
        a.push_back(sum_one / n);
        b.push_back(sum_eight / n);
    }
    const test::MeanAndError m1 = test::mean_and_error(a), m8 = test::mean_and_error(b);
    const double var1 = sqr(m1.standard_error) * kRuns, var8 = sqr(m8.standard_error) * kRuns;
    std::printf("highlight: 1 sample %.5f (var %.3g), 8 samples %.5f (var %.3g)\n", m1.mean, var1,
                m8.mean, var8);
    EXPECT_GT(m8.mean, 0.01);
    EXPECT_LT(std::abs(m8.mean - m1.mean), 4.0 * std::hypot(m1.standard_error, m8.standard_error));
    EXPECT_LT(var8, var1 / 3.0);
}

}  // namespace
}  // namespace mvpl::reference
