#include <gtest/gtest.h>

#include <string>

#include "engine/core/image.h"
#include "engine/gpu/context.h"
#include "engine/render/directional_frame.h"
#include "engine/render/vpl_renderer.h"
#include "tests/gpu/gpu_test.h"
#include "tests/render/render_test_util.h"
#include "tests/support/scene_builder.h"

namespace mvpl::render {
namespace {

using ShadowTest = gpu::testing::GpuTest;

constexpr int kShadowSize = 64;
constexpr uint32_t kShadowResolution = 64;
constexpr float kOccluderHalf = 0.25f;
constexpr float kOccluderHeight = 1.0f;

// A diffuse floor, a small square occluder above it and a point VPL above that.
scene::Scene occluder_scene(float half = kOccluderHalf) {
    scene::Scene s;
    s.materials = {test::diffuse_material(Rgb(0.5f, 0.6f, 0.7f))};
    s.meshes.push_back(test::make_quad(Vec3(-2, 0, -2), Vec3(0, 0, 4), Vec3(4, 0, 0), 0));
    s.meshes.push_back(test::make_quad(Vec3(-half, kOccluderHeight, -half), Vec3(0, 0, 2 * half),
                                       Vec3(2 * half, 0, 0), 0));
    s.camera = test::look_at(Vec3(0.0f, 3.2f, 2.2f), Vec3(0, 0, -0.1f), 0.9f);
    s.has_camera = true;
    return s;
}

light::Vpl point_vpl() {
    light::Vpl vpl;
    vpl.type = light::VplType::Point;
    vpl.position = Vec3(0.12f, 2.0f, -0.17f);
    vpl.power = Rgb(4.0f);
    return vpl;
}

RenderOptions small_options() {
    RenderOptions options;
    options.width = options.height = kShadowSize;
    options.shadow_resolution = kShadowResolution;
    options.batch = 8;
    options.clamp = 0.0f;
    return options;
}

struct ShadowStats {
    int shadowed = 0;
    int lit = 0;
    int ambiguous = 0;
    int misclassified = 0;
    float worst_lit = 0.0f;
};

// Compares the floor's pixels with exact shadow rays from each pixel to light_point(pixel): the
// GPU must show black where the ray hits the occluder and the unshadowed value elsewhere, except
// in the band where growing or shrinking the occluder by the shadow map's tolerance changes the
// exact answer (`grown`, `shrunk`).
template <class LightPoint>
ShadowStats classify(const scene::Scene& scene, const Image& image, const light::Vpl& vpl,
                     const LightPoint& light_point, const scene::Mesh& grown,
                     const scene::Mesh& shrunk) {
    ShadowStats stats;
    for (int y = 0; y < kShadowSize; ++y) {
        for (int x = 0; x < kShadowSize; ++x) {
            const std::optional<testing::CpuHit> hit =
                testing::cast_camera_ray(scene, kShadowSize, kShadowSize, x, y);
            if (!hit || hit->mesh != 0) continue;
            const Rgb expected = testing::cpu_contribution(vpl, hit->p, hit->ng,
                                                           testing::closure_of(scene.materials[0]),
                                                           scene.camera.position(), 0.0f);
            const Vec3 target = light_point(hit->p);
            const bool in_shadow = testing::segment_hits_mesh(scene.meshes[1], hit->p, target);
            const bool may_differ = testing::segment_hits_mesh(grown, hit->p, target) !=
                                    testing::segment_hits_mesh(shrunk, hit->p, target);
            const Rgb got = image.at(x, y);
            const bool gpu_shadow = got == Rgb(0.0f);
            stats.ambiguous += may_differ;
            if (gpu_shadow != in_shadow) {
                ++stats.misclassified;
                EXPECT_TRUE(may_differ)
                    << "pixel " << x << "," << y << " misclassified far from the shadow's edge";
                continue;
            }
            if (in_shadow) {
                ++stats.shadowed;
            } else {
                ++stats.lit;
                const float error =
                    max_component(glm::abs(got - expected)) / max_component(expected);
                stats.worst_lit = std::max(stats.worst_lit, error);
            }
        }
    }
    return stats;
}

TEST_F(ShadowTest, AnOccluderCastsASharpShadowWithinTheShadowMapResolution) {
    const scene::Scene scene = occluder_scene();
    const light::Vpl vpl = point_vpl();
    VplRenderer renderer(context(), scene);
    const Image image = renderer.render({{vpl}}, small_options());

    // Where a shadow-map lookup may legitimately disagree with an exact shadow ray: a cube texel
    // at a face centre subtends 2/res rad (less towards the corners); the nearest lookup reads a
    // texel whose centre is up to half a texel diagonal (0.71 texels) from the receiver's
    // direction, and the rasteriser covers a texel by its centre, which moves the occluder's
    // edge by up to another half texel: 1.21 texel angles, 1.25 here. On the occluder's plane
    // (height h under the VPL, distance d) an angle θ moves a point by d²θ/h, so a floor pixel
    // is ambiguous when growing or shrinking the occluder by that much changes its exact answer;
    // every misclassified pixel must be ambiguous (measured: 25 of 216 ambiguous at res 64).
    const float theta = 1.25f * (2.0f / float(kShadowResolution));
    const float h = vpl.position.y - kOccluderHeight;
    float d_max = 0.0f;
    for (const Vec3& p : scene.meshes[1].positions)
        d_max = std::max(d_max, glm::length(p - vpl.position));
    const float delta = d_max * d_max * theta / h;
    const ShadowStats stats = classify(
        scene, image, vpl, [&](const Vec3&) { return vpl.position; },
        occluder_scene(kOccluderHalf + delta).meshes[1],
        occluder_scene(kOccluderHalf - delta).meshes[1]);
    EXPECT_GT(stats.shadowed, 50);
    EXPECT_GT(stats.lit, 1000);
    EXPECT_LT(stats.worst_lit, 1e-3f);
    RecordProperty("misclassified", stats.misclassified);
    RecordProperty("ambiguous", stats.ambiguous);
}

TEST_F(ShadowTest, ADirectionalVplCastsAShadowThroughItsOrthographicMap) {
    constexpr float kHalf = 0.5f;
    const scene::Scene scene = occluder_scene(kHalf);
    light::Vpl vpl;
    vpl.type = light::VplType::Directional;
    vpl.normal = glm::normalize(Vec3(0.25f, -1.0f, 0.15f));
    vpl.power = Rgb(1.5f, 1.0f, 0.5f);
    VplRenderer renderer(context(), scene);
    const Image image = renderer.render({{vpl}}, small_options());

    // The map's texels are extent/res wide across the direction; the same 1.25-texel tolerance
    // as for cubes, carried onto the occluder's plane (normal +y) by 1/|dir.y|.
    scene::Bounds bounds;
    for (const scene::Mesh& mesh : scene.meshes) {
        for (const Vec3& p : mesh.positions)
            bounds.extend(p);
    }
    const float texel = directional_frame(vpl.normal, bounds).extent / float(kShadowResolution);
    const float delta = 1.25f * texel / std::abs(vpl.normal.y);
    const float far = 10.0f * bounds.diagonal();
    const ShadowStats stats = classify(
        scene, image, vpl, [&](const Vec3& p) { return p - far * vpl.normal; },
        occluder_scene(kHalf + delta).meshes[1], occluder_scene(kHalf - delta).meshes[1]);
    EXPECT_GT(stats.shadowed, 100);
    EXPECT_GT(stats.lit, 1000);
    EXPECT_LT(stats.worst_lit, 1e-3f);
    RecordProperty("misclassified", stats.misclassified);
    RecordProperty("ambiguous", stats.ambiguous);
}

TEST_F(ShadowTest, TheImageDoesNotDependOnTheSceneScale) {
    const std::vector<float> scales = {1.0f, 1e-3f, 1e4f};
    std::vector<Image> images;
    for (float s : scales) {
        scene::Scene scene = occluder_scene();
        test::scale_scene(scene, s);
        std::vector<light::Vpl> vpls = {point_vpl(), point_vpl()};
        // A Surface VPL facing down beside the occluder: a second shadow, and a hemicube.
        vpls[1].type = light::VplType::Surface;
        vpls[1].position = Vec3(1.2f, 0.9f, 0.4f);
        vpls[1].normal = vpls[1].shading_normal = Vec3(0, -1, 0);
        vpls[1].wi = glm::normalize(Vec3(0.3f, -1.0f, 0.1f));
        vpls[1].closure = material::ClosureParams{};
        for (light::Vpl& v : vpls) {
            v.position *= s;
            v.power *= s * s;  // the same irradiance at s times the distance
        }
        light::Vpl sun;  // irradiance does not depend on distance: its power stays
        sun.type = light::VplType::Directional;
        sun.normal = glm::normalize(Vec3(-0.3f, -1.0f, 0.2f));
        sun.power = Rgb(0.4f);
        vpls.push_back(sun);
        VplRenderer renderer(context(), scene);
        RenderOptions options = small_options();
        options.clamp = 0.02f;  // relative to the scene's diagonal: scales along
        images.push_back(renderer.render({vpls}, options));
    }
    for (size_t i = 1; i < images.size(); ++i) {
        int differ = 0;
        for (int y = 0; y < kShadowSize; ++y) {
            for (int x = 0; x < kShadowSize; ++x) {
                const Rgb a = images[0].at(x, y);
                const Rgb b = images[i].at(x, y);
                const float scale = std::max(max_component(a), max_component(b));
                if (scale > 0.0f && max_component(glm::abs(a - b)) > 1e-3f * scale) ++differ;
            }
        }
        // Float rounding may flip a pixel exactly on a shadow edge, never more.
        EXPECT_LE(differ, 2) << "scale " << scales[i];
        RecordProperty("differing_pixels_at_scale_" + std::to_string(i), differ);
    }
    EXPECT_GT(images[0].mean().g, 0.0f);
}

}  // namespace
}  // namespace mvpl::render
