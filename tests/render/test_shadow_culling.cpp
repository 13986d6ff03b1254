// Shadow culling (issue 14): a cube face draws only the triangle clusters that can reach its
// frustum and the VPL's lit half-space. It must never drop a triangle that can cover a texel the
// shading pass reads: on the CPU against brute force over points of every triangle, and on the
// GPU as the same image with culling on and off.
#include <gtest/gtest.h>

#include <random>

#include "engine/core/image_metrics.h"
#include "engine/render/shadow_clusters.h"
#include "engine/render/vpl_renderer.h"
#include "engine/scene/scene_loader.h"
#include "tests/gpu/gpu_test.h"
#include "tests/support/scene_builder.h"
#include "tests/support/vpl_render.h"

namespace mvpl::render {
namespace {

// The Cornell box with icospheres of `subdivisions` levels and radius `size` × the box's
// smallest side, centred at the given fractions of the box.
scene::Scene box_with_spheres(std::initializer_list<Vec3> centres, float size, int subdivisions) {
    scene::Scene s = scene::load_scene(MVPL_ASSETS_DIR "/cornell-box/cbox.gltf");
    const scene::Bounds b = s.bounds();
    const Vec3 extent = b.hi - b.lo;
    const float radius = size * std::min({extent.x, extent.y, extent.z});
    for (const Vec3& at : centres)
        s.meshes.push_back(
            test::make_icosphere(b.lo + at * extent, radius, subdivisions, false, 0));
    return s;
}

// A few finely tessellated spheres: many clusters, spread out.
scene::Scene box_with_spheres() {
    return box_with_spheres(
        {Vec3(0.3f, 0.2f, 0.4f), Vec3(0.7f, 0.5f, 0.6f), Vec3(0.5f, 0.8f, 0.3f)}, 0.08f, 4);
}

// Whether point x lies in face `face` of the cube at p (its closed frustum) and, with a normal,
// on the lit side of the VPL's plane.
bool in_face(const Vec3& x, const Vec3& p, uint32_t face, const Vec3* normal) {
    const Vec3 r = x - p;
    const int axis = int(face / 2);
    const float along = (face % 2 == 0 ? 1.0f : -1.0f) * r[axis];
    const bool frustum =
        along >= std::abs(r[(axis + 1) % 3]) && along >= std::abs(r[(axis + 2) % 3]);
    return frustum && (!normal || glm::dot(*normal, r) >= 0.0f);
}

TEST(ShadowClusters, CullingKeepsEveryTriangleThatReachesTheFace) {
    const scene::Scene s = box_with_spheres();
    const ShadowClusters clusters(s, 64);
    ASSERT_GT(clusters.clusters().size(), 100u);
    const std::vector<Vec3>& pos = clusters.positions();
    const std::vector<uint32_t>& idx = clusters.indices();
    const scene::Bounds b = s.bounds();
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    CasterRanges ranges;
    // The triangles of every group's full level: what LodChoice{} draws.
    std::vector<bool> full(idx.size() / 3, false);
    clusters.level_ranges(Vec3(0.0f), LodChoice{}, ranges);
    for (size_t kind = 0; kind < 4; ++kind) {
        ASSERT_TRUE((kind & CasterRanges::kSimplified) == 0 || ranges.by_kind[kind].empty());
        for (const gpu::IndexRange& r : ranges.by_kind[kind]) {
            for (uint32_t t = r.first_index / 3; t < (r.first_index + r.index_count) / 3; ++t)
                full[t] = true;
        }
    }
    size_t kept = 0, total = 0;
    for (int trial = 0; trial < 12; ++trial) {
        const Vec3 p = b.lo + Vec3(u(rng), u(rng), u(rng)) * (b.hi - b.lo);
        const Vec3 n = glm::normalize(Vec3(u(rng), u(rng), u(rng)) - 0.5f);
        for (uint32_t face = 0; face < 6; ++face) {
            for (const Vec3* normal : {static_cast<const Vec3*>(nullptr), &n}) {
                clusters.visible_ranges(p, face, normal, 0.0f, LodChoice{}, ranges);
                std::vector<bool> drawn(idx.size() / 3, false);
                for (const std::vector<gpu::IndexRange>& kind : ranges.by_kind) {
                    for (const gpu::IndexRange& r : kind) {
                        for (uint32_t t = r.first_index / 3;
                             t < (r.first_index + r.index_count) / 3; ++t)
                            drawn[t] = true;
                    }
                }
                for (size_t t = 0; t < drawn.size(); ++t) {
                    if (!full[t]) continue;  // a coarser level's
                    total += 1;
                    kept += drawn[t] ? 1 : 0;
                    if (drawn[t]) continue;
                    // Points of the triangle on a barycentric grid, its corners included.
                    const Vec3 a = pos[idx[3 * t]], e1 = pos[idx[3 * t + 1]] - a,
                               e2 = pos[idx[3 * t + 2]] - a;
                    for (int i = 0; i <= 3; ++i) {
                        for (int j = 0; i + j <= 3; ++j) {
                            const Vec3 x = a + (float(i) / 3.0f) * e1 + (float(j) / 3.0f) * e2;
                            ASSERT_FALSE(in_face(x, p, face, normal))
                                << "trial " << trial << " face " << face << " triangle " << t;
                        }
                    }
                }
            }
        }
    }
    // And it culls: a face with the lit half-space keeps far less than everything.
    EXPECT_LT(double(kept), 0.5 * double(total));
}

using ShadowCullingTest = gpu::testing::GpuTest;

// Culled faces hold the same nearest distances as faces with every triangle, so the images are
// the same to the bit: emitter (area) and surface VPLs, default and coarse faces.
TEST_F(ShadowCullingTest, ImagesAreTheSameWithCullingOnAndOff) {
    const scene::Scene s = box_with_spheres();
    const light::VplSet vpls = test::monte_carlo_vpls(s, 24, 6, 5);
    ASSERT_GT(vpls.vpls.size(), 24u);
    VplRenderer renderer(context(), s);
    for (const uint32_t shadow_res : {16u, 128u}) {
        RenderOptions o;
        o.width = o.height = 48;
        o.shadow_resolution = shadow_res;
        o.shadow_culling = true;
        RenderTimings culled_timings;
        const Image culled = renderer.render(vpls, o, &culled_timings);
        o.shadow_culling = false;
        RenderTimings full_timings;
        const Image full = renderer.render(vpls, o, &full_timings);
        EXPECT_LT(culled_timings.shadow_triangles, full_timings.shadow_triangles / 2);
        size_t differing = 0;
        for (size_t i = 0; i < full.pixels().size(); ++i)
            differing += culled.pixels()[i] != full.pixels()[i] ? 1 : 0;
        EXPECT_EQ(differing, 0u) << "shadow faces " << shadow_res;
        EXPECT_GT(full.mean().r, 0.0f);
    }
}

// One sphere of 20480 triangles (above the proxy's threshold) near the floor.
scene::Scene box_with_dense_sphere() {
    return box_with_spheres({Vec3(0.5f, 0.25f, 0.5f)}, 0.2f, 5);
}

TEST(ShadowProxy, SimplifiesLargeMeshesOnly) {
    const scene::Scene s = box_with_dense_sphere();
    const ShadowClusters clusters(s);
    EXPECT_EQ(clusters.triangle_count(0), s.triangle_count());
    // The sphere shrinks; the box's walls (small meshes) are kept as they are.
    const uint32_t proxy = ShadowClusters::kProxyLevel;
    EXPECT_LT(clusters.triangle_count(proxy), s.triangle_count() / 3);
    EXPECT_GT(clusters.triangle_count(proxy),
              s.triangle_count() - s.meshes.back().triangle_count());
    // Without levels of detail, one level of everything.
    const ShadowClusters flat(s, ShadowClusters::kClusterTriangles, false);
    EXPECT_EQ(flat.triangle_count(proxy), s.triangle_count());
    EXPECT_EQ(flat.groups().size(), 1u);
}

// The proxy's error is the shadow maps' business only where surface VPLs are shadowed: images
// of emitter VPLs are the same to the bit, and the whole image stays as close to the oracle as
// with full maps (the bound: within 1.2× of the full maps' error).
TEST_F(ShadowCullingTest, ProxyCostsNoMoreThanAFifthOfTheShadowMapError) {
    const scene::Scene s = box_with_dense_sphere();
    const light::VplSet vpls = test::monte_carlo_vpls(s, 96, 6, 11);
    light::VplSet emitters;
    for (const light::Vpl& v : vpls.vpls) {
        if (v.path_length == 0) emitters.vpls.push_back(v);
    }
    emitters.scale = vpls.scale;
    ASSERT_LT(emitters.vpls.size(), vpls.vpls.size());
    VplRenderer renderer(context(), s);
    RenderOptions o;
    o.width = o.height = 64;
    o.shadow_resolution = 128;
    auto render = [&](const light::VplSet& set, bool proxy) {
        o.shadow_proxy = proxy;
        return renderer.render(set, o);
    };
    const Image with = render(emitters, true);
    const Image without = render(emitters, false);
    for (size_t i = 0; i < with.pixels().size(); ++i)
        ASSERT_EQ(with.pixels()[i], without.pixels()[i]) << "pixel " << i;

    const Image oracle = test::oracle_render(s, vpls, {.res = 64});
    const double full = compare_images(render(vpls, false), oracle).rel_mse;
    const double proxy = compare_images(render(vpls, true), oracle).rel_mse;
    EXPECT_LE(proxy, 1.2 * full) << "full maps " << full;
    EXPECT_GT(oracle.mean().r, 0.0f);
}

}  // namespace
}  // namespace mvpl::render
