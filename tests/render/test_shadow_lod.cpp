// Levels of detail for shadow casters (issue 14, "coarser shadow geometry"): a large mesh far
// from a VPL is drawn simplified, by no more than kLodFootprint (one) shadow texel footprint at its
// distance. On the CPU: each level's error bound holds on a sphere (whose surface is known), and
// the choice follows the distance. On the GPU: far fewer triangles, at the error of full maps
// against the CPU oracle's exact visibility (the bound: within 1.2×), for cube faces and
// for directional VPLs' orthographic maps.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <map>
#include <set>

#include "engine/core/image_metrics.h"
#include "engine/render/shadow_clusters.h"
#include "engine/render/shadow_pass.h"
#include "engine/render/vpl_renderer.h"
#include "engine/scene/scene_loader.h"
#include "tests/gpu/gpu_test.h"
#include "tests/support/scene_builder.h"
#include "tests/support/vpl_render.h"

namespace mvpl::render {
namespace {

struct Sphere {
    Vec3 centre;
    float radius;
};

// The Cornell box with one sphere of 20480 triangles near the floor.
scene::Scene box_with_dense_sphere(Sphere& sphere) {
    scene::Scene s = scene::load_scene(MVPL_ASSETS_DIR "/cornell-box/cbox.gltf");
    const scene::Bounds b = s.bounds();
    const Vec3 extent = b.hi - b.lo;
    sphere = {b.lo + Vec3(0.5f, 0.25f, 0.5f) * extent,
              0.2f * std::min({extent.x, extent.y, extent.z})};
    s.meshes.push_back(test::make_icosphere(sphere.centre, sphere.radius, 5, false, 0));
    return s;
}

TEST(ShadowLevels, EachLevelKeepsItsErrorBoundOnASphere) {
    Sphere sphere{};
    const scene::Scene s = box_with_dense_sphere(sphere);
    const ShadowClusters clusters(s);
    // The sphere's two chunks (20480 triangles: at least twice kLodChunkTriangles), then the
    // box's walls, pooled.
    ASSERT_EQ(clusters.groups().size(), 3u);
    EXPECT_EQ(clusters.groups()[0].levels[0].triangle_count +
                  clusters.groups()[1].levels[0].triangle_count,
              20480u);
    const std::vector<Vec3>& p = clusters.positions();
    const std::vector<uint32_t>& idx = clusters.indices();
    for (size_t chunk = 0; chunk < 2; ++chunk) {
        const ShadowGroup& g = clusters.groups()[chunk];
        ASSERT_GE(g.levels.size(), 4u);
        EXPECT_EQ(g.levels[0].error, 0.0f);
        // The vertices are the sphere's, so a level's surface lies inside it: its distance from
        // the sphere is largest inside a triangle. Sampled at the centroid and the edges'
        // midpoints (a flat triangle's farthest point from a concentric sphere is its foot of the
        // perpendicular from the centre, inside it for these near-equilateral ones: the centroid
        // is within a few percent of it).
        auto deepest = [&](const ShadowLevel& level) {
            float depth = 0.0f;
            for (uint32_t c = 0; c < level.cluster_count; ++c) {
                const ShadowCluster& cl = clusters.clusters()[level.first_cluster + c];
                for (uint32_t i = cl.first_index; i < cl.first_index + cl.index_count; i += 3) {
                    const Vec3 a = p[idx[i]], b = p[idx[i + 1]], d = p[idx[i + 2]];
                    for (const Vec3& x :
                         {(a + b + d) / 3.0f, 0.5f * (a + b), 0.5f * (b + d), 0.5f * (a + d)})
                        depth = std::max(depth, sphere.radius - glm::length(x - sphere.centre));
                }
            }
            return depth;
        };
        // The full level, the icosphere itself, lies 2.4·10⁻⁴ R inside the sphere.
        const float mesh_depth = deepest(g.levels[0]);
        EXPECT_LT(mesh_depth, 3e-4f * sphere.radius);
        for (size_t k = 1; k < g.levels.size(); ++k) {
            const ShadowLevel& level = g.levels[k];
            EXPECT_LT(level.triangle_count, g.levels[k - 1].triangle_count) << "level " << k;
            EXPECT_GT(level.error, g.levels[k - 1].error) << "level " << k;
            // The bound holds from the mesh (so from the sphere, adding the mesh's own depth),
            // and it is not loose by more than 4×.
            const float depth = deepest(level);
            EXPECT_LE(depth, level.error + mesh_depth)
                << "level " << k << " of " << g.levels.size();
            EXPECT_GT(depth, 0.25f * level.error) << "level " << k;
        }
    }
}

// Chunks of one mesh meet without cracks at every pair of levels: their borders are locked, so
// every edge that a chunk's level has on its border is an edge of the neighbour's full level
// (and the full levels of the two chunks share their border edges).
TEST(ShadowLevels, ChunksMeetAtTheSameEdgesAtEveryLevel) {
    Sphere sphere{};
    const scene::Scene s = box_with_dense_sphere(sphere);
    const ShadowClusters clusters(s);
    ASSERT_EQ(clusters.groups().size(), 3u);
    const std::vector<Vec3>& p = clusters.positions();
    const std::vector<uint32_t>& idx = clusters.indices();
    using Edge = std::pair<std::array<float, 3>, std::array<float, 3>>;
    auto key = [&](uint32_t a, uint32_t b) {
        std::array<float, 3> u{p[a].x, p[a].y, p[a].z}, v{p[b].x, p[b].y, p[b].z};
        return u < v ? Edge{u, v} : Edge{v, u};
    };
    // Edges used once within a level: its border (the sphere is closed, so only chunk borders).
    auto border = [&](const ShadowLevel& level) {
        std::map<Edge, int> uses;
        for (uint32_t c = 0; c < level.cluster_count; ++c) {
            const ShadowCluster& cl = clusters.clusters()[level.first_cluster + c];
            for (uint32_t i = cl.first_index; i < cl.first_index + cl.index_count; i += 3) {
                for (int e = 0; e < 3; ++e)
                    ++uses[key(idx[i + e], idx[i + (e + 1) % 3])];
            }
        }
        std::set<Edge> edges;
        for (const auto& [edge, n] : uses) {
            if (n == 1) edges.insert(edge);
        }
        return edges;
    };
    const std::set<Edge> reference = border(clusters.groups()[0].levels[0]);
    ASSERT_GT(reference.size(), 20u);
    EXPECT_EQ(border(clusters.groups()[1].levels[0]), reference);
    for (size_t chunk = 0; chunk < 2; ++chunk) {
        for (const ShadowLevel& level : clusters.groups()[chunk].levels)
            EXPECT_EQ(border(level), reference) << "chunk " << chunk;
    }
}

TEST(ShadowLevels, TheLevelFollowsTheDistance) {
    Sphere sphere{};
    const scene::Scene s = box_with_dense_sphere(sphere);
    const ShadowClusters clusters(s);
    const ShadowGroup& g = clusters.groups().front();
    LodChoice lod;
    lod.error_per_distance = ShadowPass::kLodFootprint * 2.0f / 128.0f;
    uint32_t previous = 0;
    for (const float radii : {0.0f, 0.01f, 0.1f, 0.5f, 1.0f, 4.0f, 16.0f, 1e3f}) {
        const float distance = radii * g.radius;
        // Above the middle of the group's box: `distance` from it.
        const Vec3 at(g.centre.x, g.hi.y + distance, g.centre.z);
        const uint32_t level = clusters.level_for(g, at, lod);
        EXPECT_GE(level, previous) << "distance " << distance;
        EXPECT_LE(g.levels[level].error, lod.error_per_distance * distance * 1.0001f);
        if (level + 1 < g.levels.size()) {
            EXPECT_GT(g.levels[level + 1].error, lod.error_per_distance * distance * 0.9999f);
        }
        previous = level;
    }
    EXPECT_EQ(previous, g.levels.size() - 1);  // far enough: the coarsest
    // Inside the mesh's box, its full triangles whatever the allowance per distance: a coarser
    // copy of the surface a VPL lies on would stand in front of it. Without an allowance, the
    // full triangles even far away.
    EXPECT_EQ(clusters.level_for(g, g.centre, lod), 0u);
    EXPECT_EQ(clusters.level_for(g, g.centre + Vec3(1e3f), LodChoice{}), 0u);
}

using ShadowLodTest = gpu::testing::GpuTest;

struct LodErrors {
    double full = 0.0;  // relMSE against the oracle, full meshes
    double lod = 0.0;   // with levels of detail
    uint64_t full_triangles = 0;
    uint64_t lod_triangles = 0;
};

LodErrors lod_errors(gpu::Context& context, const scene::Scene& s, const light::VplSet& vpls) {
    VplRenderer renderer(context, s);
    RenderOptions o;
    o.width = o.height = 64;
    o.shadow_resolution = 128;
    LodErrors e;
    const Image oracle = test::oracle_render(s, vpls, {.res = 64});
    EXPECT_GT(oracle.mean().r, 0.0f);
    for (const bool lod : {false, true}) {
        o.shadow_lod = lod;
        RenderTimings t;
        const double error = compare_images(renderer.render(vpls, o, &t), oracle).rel_mse;
        (lod ? e.lod : e.full) = error;
        (lod ? e.lod_triangles : e.full_triangles) = t.shadow_triangles;
    }
    std::printf(
        "relMSE against the oracle: full %.4g, levels of detail %.4g; triangles %llu, %llu\n",
        e.full, e.lod, (unsigned long long)e.full_triangles, (unsigned long long)e.lod_triangles);
    return e;
}

// Cube faces: the area light's and the surface VPLs'.
TEST_F(ShadowLodTest, CubeFacesDrawFewerTrianglesAtTheFullMapsError) {
    Sphere sphere{};
    const scene::Scene s = box_with_dense_sphere(sphere);
    const LodErrors e = lod_errors(context(), s, test::monte_carlo_vpls(s, 96, 6, 11));
    EXPECT_LT(e.lod_triangles, e.full_triangles * 3 / 4);
    EXPECT_LE(e.lod, 1.2 * e.full) << "full maps " << e.full;
}

// A floor with dense spheres under a directional light: each directional VPL draws an
// orthographic map of the whole scene, where a sphere covers a few texels.
TEST_F(ShadowLodTest, OrthographicMapsDrawFewerTrianglesAtTheFullMapsError) {
    std::vector<scene::Mesh> spheres;
    for (const Vec3& c : {Vec3(-1.0f, 0.3f, 0.0f), Vec3(0.8f, 0.5f, -0.6f), Vec3(0.4f, 0.3f, 1.2f)})
        spheres.push_back(test::make_icosphere(c, 0.3f, 5, false, 0));
    const scene::Scene s = test::floor_under_sun(std::move(spheres));
    const LodErrors e = lod_errors(context(), s, test::monte_carlo_vpls(s, 64, 3, 5));
    EXPECT_LT(e.lod_triangles, e.full_triangles / 4);
    EXPECT_LE(e.lod, 1.2 * e.full) << "full maps " << e.full;
}

}  // namespace
}  // namespace mvpl::render
