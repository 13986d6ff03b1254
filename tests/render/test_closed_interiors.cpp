// Closed interiors lit from inside (issue 32, "the shadow proxy's lost light"): every surface a VPL
// lies on faces the others, so a simplified copy of it standing a little in front of the VPL hides
// everything the VPL lights. Spheres at tessellations below and above every level-of-detail
// threshold (ShadowClusters::kLodMinTriangles, twice kLodChunkTriangles), and the insides of a
// closed cylinder and of a dome, each with a point light inside: the GPU with its default shadow
// levers against the CPU oracle (exact visibility) over the same VPLs, and the spheres against
// their analytic radiance.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/core/image_metrics.h"
#include "engine/render/shadow_clusters.h"
#include "tests/gpu/gpu_test.h"
#include "tests/support/scene_builder.h"
#include "tests/support/vpl_render.h"

namespace mvpl::render {
namespace {

constexpr float kAlbedo = 0.5f;
// The light tracer's default (Mitsuba's max_depth): VPLs of path length 0 … kMaxDepth − 2.
constexpr int kMaxDepth = 6;

// A closed surface of revolution about +Y, faces and normals inwards: the polyline `profile` of
// (radius, height) points revolved in `segments` steps, each of its pieces cut into `rows`. Each
// piece has its own vertices (a crease between pieces, as a cylinder's rim).
scene::Mesh revolve(const std::vector<Vec2>& profile, int segments, int rows) {
    scene::Mesh mesh;
    for (size_t piece = 0; piece + 1 < profile.size(); ++piece) {
        const Vec2 a = profile[piece];
        const Vec2 b = profile[piece + 1];
        const Vec2 along = glm::normalize(b - a);
        // The profile runs counter-clockwise seen from outside, so (along.y, −along.x) points out.
        const Vec2 out(along.y, -along.x);
        const uint32_t first = uint32_t(mesh.positions.size());
        for (int r = 0; r <= rows; ++r) {
            const Vec2 p = a + (b - a) * (float(r) / float(rows));
            for (int s = 0; s < segments; ++s) {
                const float phi = 2.0f * kPi * float(s) / float(segments);
                const Vec3 radial(std::cos(phi), 0.0f, -std::sin(phi));
                mesh.positions.push_back(p.x * radial + Vec3(0.0f, p.y, 0.0f));
                mesh.normals.push_back(-(out.x * radial + Vec3(0.0f, out.y, 0.0f)));
            }
        }
        for (int r = 0; r < rows; ++r) {
            for (int s = 0; s < segments; ++s) {
                const uint32_t i0 = first + uint32_t(r * segments + s);
                const uint32_t i1 = first + uint32_t(r * segments + (s + 1) % segments);
                const uint32_t j0 = i0 + uint32_t(segments);
                const uint32_t j1 = i1 + uint32_t(segments);
                mesh.indices.insert(mesh.indices.end(), {i0, j0, i1, i1, j0, j1});
            }
        }
    }
    return mesh;
}

// A point light of intensity 10 W/sr at `light`, in a diffuse enclosure; the camera inside.
scene::Scene enclosure(scene::Mesh mesh, const Vec3& light, const Vec3& eye, const Vec3& target) {
    scene::Scene s;
    s.materials = {test::diffuse_material(Rgb(kAlbedo))};
    mesh.material = 0;
    s.meshes = {std::move(mesh)};
    scene::Light l;
    l.type = scene::LightType::Point;
    l.intensity = Rgb(10.0f);
    l.position = light;
    s.lights = {l};
    s.camera = test::look_at(eye, target, 1.0f);
    s.has_camera = true;
    return s;
}

struct Renders {
    Image gpu;
    Image oracle;
};

// Both renderers over the same VPLs: 48 light paths, no clamping (so that nothing but
// visibility differs), the oracle's sub-pixel positions.
Renders render_both(gpu::Context& context, const scene::Scene& s) {
    const light::VplSet vpls = test::monte_carlo_vpls(s, 48, kMaxDepth, 5);
    test::VplRenderSettings settings;
    settings.res = 48;
    settings.clamp = 0.0f;
    return {test::gpu_render(context, s, vpls, settings), test::oracle_render(s, vpls, settings)};
}

// GPU against the oracle. Nothing occludes inside a convex enclosure, and at the creases of the
// others (a cylinder's rims, the dome's foot) only the shadow test's own allowance differs, so
// the means agree to within the shadow maps' grazing-angle error, which the full geometry
// measures at below 0.3 % here; a lost bounce moves the mean by ≥ 25 %.
void expect_gpu_matches_oracle(const Renders& r) {
    const ImageError e = compare_images(r.gpu, r.oracle);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(e.mean_ratio[c], 1.0, 0.01) << "channel " << c;
    EXPECT_LT(e.rel_mse, 1e-3);
    EXPECT_GT(r.oracle.mean().g, 0.0f);
}

class ClosedSphere : public gpu::testing::GpuTest, public ::testing::WithParamInterface<int> {};

// The radiance inside a closed Lambertian sphere of radius R with a point light I at its centre,
// the VPLs' bounces summed up to path length kMaxDepth − 2: L = a·I/(π R²) · Σ_{k=0}^{K} a^k
// (test_integrating_sphere.cpp derives the unbounded sum). Every VPL on the sphere lights every
// receiver on it with the same geometry term 1/(4R²), so the VPLs' positions add no noise: the
// 2 % are the facets' distance from the sphere (0.3 % at 1280 triangles) and the light tracer's
// Russian roulette.
TEST_P(ClosedSphere, MatchesTheAnalyticRadianceAndTheOracle) {
    const int subdivisions = GetParam();
    const float radius = 2.0f;
    const scene::Scene s =
        enclosure(test::make_icosphere(Vec3(0.0f), radius, subdivisions, true, 0), Vec3(0.0f),
                  Vec3(0.0f, 0.0f, 0.5f * radius), Vec3(0.0f, 0.0f, -radius));
    const ShadowClusters clusters(s);
    std::printf("%zu triangles, %zu shadow groups\n", s.meshes[0].triangle_count(),
                clusters.groups().size());
    const Renders r = render_both(context(), s);
    double bounces = 0.0;
    for (int k = 0; k <= kMaxDepth - 2; ++k)
        bounces += std::pow(double(kAlbedo), k);
    const double expected = kAlbedo * 10.0 / (kPi * radius * radius) * bounces;
    EXPECT_NEAR(r.gpu.mean().g / expected, 1.0, 0.02) << "GPU " << r.gpu.mean().g;
    EXPECT_NEAR(r.oracle.mean().g / expected, 1.0, 0.02) << "oracle " << r.oracle.mean().g;
    expect_gpu_matches_oracle(r);
}

// 1280 triangles: below the levels of detail; 5120: one group with levels; 81920: ten chunks.
INSTANTIATE_TEST_SUITE_P(Tessellations, ClosedSphere, ::testing::Values(3, 4, 6));

using ClosedInterior = gpu::testing::GpuTest;

// A closed cylinder of radius 1 and height 2 (8192 triangles, above kLodMinTriangles).
TEST_F(ClosedInterior, CylinderMatchesTheOracle) {
    const std::vector<Vec2> profile{{0.0f, -1.0f}, {1.0f, -1.0f}, {1.0f, 1.0f}, {0.0f, 1.0f}};
    const scene::Scene s = enclosure(revolve(profile, 128, 16), Vec3(0.0f, 0.3f, 0.0f),
                                     Vec3(0.0f, -0.5f, 0.6f), Vec3(0.0f, 0.2f, -1.0f));
    ASSERT_GT(s.meshes[0].triangle_count(), ShadowClusters::kLodMinTriangles);
    expect_gpu_matches_oracle(render_both(context(), s));
}

// A dome: a hemisphere of radius 1 on a flat floor (12544 triangles), the light near its top.
TEST_F(ClosedInterior, DomeMatchesTheOracle) {
    std::vector<Vec2> profile{{0.0f, 0.0f}};
    for (int i = 0; i <= 48; ++i) {
        const float theta = 0.5f * kPi * float(i) / 48.0f;
        profile.emplace_back(std::cos(theta), std::sin(theta));
    }
    profile.back().x = 0.0f;
    const scene::Scene s = enclosure(revolve(profile, 128, 1), Vec3(0.0f, 0.7f, 0.0f),
                                     Vec3(0.0f, 0.2f, 0.7f), Vec3(0.0f, 0.3f, -1.0f));
    ASSERT_GT(s.meshes[0].triangle_count(), ShadowClusters::kLodMinTriangles);
    expect_gpu_matches_oracle(render_both(context(), s));
}

}  // namespace
}  // namespace mvpl::render
