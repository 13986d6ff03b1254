// The AOVs (engine/aov) against analytic answers: a Lambertian plane's base colour, normal, depth
// (distance from the eye along the ray) and position, averaged over the render's own sub-pixel
// positions, so that a pixel an edge crosses holds the covered fraction; a mirror's pixels report
// the diffuse wall its specular chain ends on; the reference's AOVs over its own samples.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "engine/aov/aov_images.h"
#include "engine/aov/aov_kind.h"
#include "engine/core/error.h"
#include "engine/core/subpixel.h"
#include "engine/light/light_sampler.h"
#include "engine/render/vpl_renderer.h"
#include "engine/scene/camera.h"
#include "engine/trace/accel.h"
#include "tests/support/scene_builder.h"

namespace mvpl::aov {
namespace {

constexpr int kWidth = 16;
constexpr int kHeight = 12;
constexpr float kPlaneZ = -2.0f;
const Rgb kBase(0.2f, 0.5f, 0.7f);

// What one sub-pixel ray should report (aov_tracer.h), worked out without the tracer.
struct Expected {
    Rgb albedo{0.0f};
    Vec3 normal{0.0f};
    Vec3 position{0.0f};
    float depth = 0.0f;
    void add(const Expected& e, float w) {
        albedo += e.albedo * w;
        normal += e.normal * w;
        position += e.position * w;
        depth += e.depth * w;
    }
};

// The camera at the origin looking down −Z at a plane z = kPlaneZ facing it, which covers
// x ≥ edge_x (it reaches far past the view everywhere else).
scene::Scene plane_scene(float edge_x) {
    scene::Scene s;
    s.materials = {test::diffuse_material(kBase)};
    s.meshes.push_back(
        test::make_quad(Vec3(edge_x, -50, kPlaneZ), Vec3(200, 0, 0), Vec3(0, 100, 0), 0));
    s.camera = test::look_at(Vec3(0.0f), Vec3(0, 0, -1), 0.8f);
    s.has_camera = true;
    return s;
}

// The ray through `film` against the plane: t from the eye, hit where x ≥ edge_x.
Expected plane_answer(const scene::Camera& camera, Vec2 film, float edge_x) {
    const scene::CameraRay r = scene::generate_camera_ray(camera, kWidth, kHeight, film);
    const float t = kPlaneZ / r.direction.z;  // the eye is the origin
    const Vec3 p = t * r.direction;
    if (p.x < edge_x) return {};
    return Expected{kBase, Vec3(0, 0, 1), p, t};
}

std::vector<AovRequest> all_aovs() {
    return parse_aov_list("albedo,normal,depth,position", "--aov");
}

// A render's estimate of kWidth × kHeight, its positions those of `vpls` VPLs at 32 a position.
integrator::Estimate estimate_of(uint64_t seed) {
    integrator::Estimate e;
    e.render.width = kWidth;
    e.render.height = kHeight;
    e.render.batch = 32;
    e.render.batches_per_position = 1;
    e.render.subpixel_rotation = subpixel_rotation(seed);
    e.render.chain_seed = seed;
    e.sampling.seed = seed;
    return e;
}

// Pixel (x, y) of the AOV images against `want`: albedo and normal within `tol`, depth and
// position within `geometric_tol`; returns the depth's error.
float expect_pixel(const std::vector<ChannelImage>& images, int x, int y, const Expected& want,
                   float tol, float geometric_tol) {
    EXPECT_EQ(images.size(), 4u);
    const size_t p = size_t(y) * kWidth + size_t(x);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(images[0].values[3 * p + c], want.albedo[c], tol) << x << "," << y;
        EXPECT_NEAR(images[1].values[3 * p + c], want.normal[c], tol) << x << "," << y;
        EXPECT_NEAR(images[3].values[3 * p + c], want.position[c], geometric_tol) << x << "," << y;
    }
    EXPECT_NEAR(images[2].values[p], want.depth, geometric_tol) << x << "," << y;
    return std::abs(images[2].values[p] - want.depth);
}

// Float rounding of a ray–plane hit a few metres away, averaged over positions.
constexpr float kExact = 2e-6f;
constexpr float kExactGeometry = 2e-5f;

struct Rendered {
    scene::Scene scene;
    std::unique_ptr<trace::Accel> accel;
    std::unique_ptr<light::LightSampler> lights;
    std::vector<ChannelImage> images;
};

Rendered render_of(scene::Scene scene, const integrator::Estimate& e, uint64_t vpls) {
    Rendered r{std::move(scene), nullptr, nullptr, {}};
    r.accel = std::make_unique<trace::Accel>(r.scene);
    r.lights = std::make_unique<light::LightSampler>(r.scene);
    r.images = render_aovs({&r.scene, r.accel.get(), r.lights.get(), &r.scene.camera}, e, vpls,
                           all_aovs());
    return r;
}

TEST(AovImages, NamesAndChannelsFollowTheConventions) {
    const std::vector<AovRequest> a = all_aovs();
    ASSERT_EQ(a.size(), 4u);
    EXPECT_EQ(a[0].channels, (std::vector<std::string>{"albedo.R", "albedo.G", "albedo.B"}));
    EXPECT_EQ(a[1].channels, (std::vector<std::string>{"N.X", "N.Y", "N.Z"}));
    EXPECT_EQ(a[2].channels, (std::vector<std::string>{"Z"}));
    EXPECT_EQ(a[3].channels, (std::vector<std::string>{"P.X", "P.Y", "P.Z"}));
    EXPECT_THROW(parse_aov_list("albedo,colour", "--aov"), UsageError);
    EXPECT_THROW(parse_aov_list("depth,depth", "--aov"), UsageError);
    EXPECT_THROW(parse_aov_list("", "--aov"), UsageError);
}

// Every pixel inside the plane: its base colour and normal exactly, its depth and position the
// mean of the analytic ones over the render's 20 positions (rounding only).
TEST(AovImages, APlaneReportsItsColourNormalAndAnalyticDepth) {
    const float edge = -100.0f;  // no edge in view
    const integrator::Estimate e = estimate_of(3);
    const uint64_t vpls = 32 * 20 - 5;  // the 20th position partly shaded: it counts
    const Rendered r = render_of(plane_scene(edge), e, vpls);
    const SubpixelSchedule schedule = render::subpixel_schedule(e.render);
    ASSERT_EQ(schedule.positions_after(vpls), 20u);
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            Expected want;
            for (uint64_t p = 0; p < 20; ++p) {
                const Vec2 o = schedule.position(p);
                want.add(plane_answer(r.scene.camera, Vec2(x + o.x, y + o.y), edge), 1.0f / 20);
            }
            expect_pixel(r.images, x, y, want, kExact, kExactGeometry);
        }
    }
}

// The plane's edge at x = 0.013 · depth crosses a column of pixels: each holds the plane's values
// times the fraction of the render's positions that hit it (and 0 elsewhere, as a miss reports).
TEST(AovImages, AnEdgePixelHoldsTheCoverageMix) {
    const float edge = 0.013f * -kPlaneZ;
    const integrator::Estimate e = estimate_of(11);
    const uint64_t vpls = 32 * 32;
    const Rendered r = render_of(plane_scene(edge), e, vpls);
    const SubpixelSchedule schedule = render::subpixel_schedule(e.render);
    int mixed = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            Expected want;
            int hits = 0;
            for (uint64_t p = 0; p < 32; ++p) {
                const Vec2 o = schedule.position(p);
                const Expected one = plane_answer(r.scene.camera, Vec2(x + o.x, y + o.y), edge);
                hits += one.depth > 0.0f ? 1 : 0;
                want.add(one, 1.0f / 32);
            }
            if (hits > 0 && hits < 32) ++mixed;
            expect_pixel(r.images, x, y, want, kExact, kExactGeometry);
        }
    }
    EXPECT_GE(mixed, kHeight) << "the edge should cut a column of pixels";
}

// A mirror at z = −2 turned 45° sends the view to +x, onto a diffuse wall at x = 3 facing it:
// with chains every pixel reports the wall (its colour, normal −x, where the reflected ray meets
// it, the path's length); without, the mirror itself.
TEST(AovImages, AChainedPixelReportsTheRoughSurfaceAtItsEnd) {
    scene::Scene s;
    const Rgb wall_colour(0.3f, 0.6f, 0.1f);
    scene::Material mirror;
    mirror.base_color = Rgb(0.9f);
    mirror.metallic = 1.0f;
    mirror.roughness = 0.0f;
    s.materials = {mirror, test::diffuse_material(wall_colour)};
    s.meshes.push_back(test::make_quad(Vec3(-1, -1, -1), Vec3(2, 0, -2), Vec3(0, 2, 0), 0));
    s.meshes.push_back(test::make_quad(Vec3(3, -5, -7), Vec3(0, 0, 10), Vec3(0, 10, 0), 1));
    scene::Light light;
    light.position = Vec3(1, 0, -1);
    light.intensity = Rgb(1.0f);
    s.lights.push_back(light);
    s.camera = test::look_at(Vec3(0.0f), Vec3(0, 0, -1), 0.3f);
    s.has_camera = true;
    integrator::Estimate e = estimate_of(5);
    e.render.chains.max_roughness = light::kDefaultChainRoughness;
    const uint64_t vpls = 32 * 8;
    const Rendered chained = render_of(s, e, vpls);
    e.render.chains.max_roughness = -1.0f;
    const Rendered plain = render_of(s, e, vpls);
    const SubpixelSchedule schedule = render::subpixel_schedule(e.render);
    const Vec3 n = glm::normalize(Vec3(1, 0, 1));
    std::vector<float> depth_errors;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            Expected wall, glass;
            for (uint64_t p = 0; p < 8; ++p) {
                const Vec2 o = schedule.position(p);
                const scene::CameraRay r =
                    scene::generate_camera_ray(s.camera, kWidth, kHeight, Vec2(x + o.x, y + o.y));
                const float t1 = glm::dot(n, Vec3(0, 0, -2)) / glm::dot(n, r.direction);
                const Vec3 p1 = t1 * r.direction;
                const Vec3 d2 = glm::reflect(r.direction, n);
                const float t2 = (3.0f - p1.x) / d2.x;
                wall.add(Expected{wall_colour, Vec3(-1, 0, 0), p1 + t2 * d2, t1 + t2}, 1.0f / 8);
                glass.add(Expected{Rgb(0.9f), n, p1, t1}, 1.0f / 8);
            }
            // The smooth GGX lobe's α = 10⁻⁴ (microfacet.h) tilts the mirror's facet by θ with
            // P(tan θ > t) = α²/(α² + t²): the median θ is α, 6·10⁻⁴ m over the 3 m to the wall,
            // and θ > 0.05 (0.3 m on the wall, over 8 positions 0.04 m) has probability 4·10⁻⁶
            // per ray, 0.6 % over the image's 1 536. Colour and normal: the wall's, exactly.
            depth_errors.push_back(expect_pixel(chained.images, x, y, wall, kExact, 0.04f));
            expect_pixel(plain.images, x, y, glass, kExact, kExactGeometry);
        }
    }
    // The median pixel: 8 rays' mean tilt about α, 10 times that allowed.
    std::nth_element(depth_errors.begin(), depth_errors.begin() + depth_errors.size() / 2,
                     depth_errors.end());
    EXPECT_LT(depth_errors[depth_errors.size() / 2], 6e-3f);
}

// The reference's AOVs average over its own camera samples: a plane seen whole reports its
// colour and normal exactly, its depth within the spread of the pixel's rays.
TEST(AovImages, TheReferenceReportsThePlaneOverItsSamples) {
    const scene::Scene s = plane_scene(-100.0f);
    const trace::Accel accel(s);
    reference::PathTracerOptions o;
    o.width = kWidth;
    o.height = kHeight;
    o.spp = 4;
    o.quiet = true;
    ReferenceAovs film(s, accel, o, all_aovs());
    const reference::CameraSampleHook hook = film.hook();
    std::vector<Expected> want(size_t(kWidth) * kHeight);
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            for (int k = 0; k < o.spp; ++k) {
                const Vec2 f(x + (k + 0.5f) / 4.0f, y + 0.5f);
                hook(x, y, k, f);
                want[size_t(y) * kWidth + x].add(plane_answer(s.camera, f, -100.0f), 0.25f);
            }
        }
    }
    const std::vector<ChannelImage> images = film.images(o.spp);
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x)
            expect_pixel(images, x, y, want[size_t(y) * kWidth + x], kExact, kExactGeometry);
    }
}

}  // namespace
}  // namespace mvpl::aov
