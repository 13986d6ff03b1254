// Back-face culling of solids in the shadow maps (issue 14, "fewer triangles per face"): a large
// closed mesh seen by a VPL outside its box draws only its faces towards the VPL, since a ray from
// outside a solid enters it through a front face before it meets a back face. On the CPU: which
// meshes bound a solid, and which VPLs see them from outside. On the GPU: the same image with the
// rasteriser culling the back faces as with both faces drawn, on a concave solid (a torus), for
// cube faces and orthographic maps.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/core/image_metrics.h"
#include "engine/gpu/context.h"
#include "engine/render/closed_surface.h"
#include "engine/render/directional_frame.h"
#include "engine/render/scene_geometry.h"
#include "engine/render/shadow_clusters.h"
#include "engine/render/shadow_pass.h"
#include "engine/render/vpl_renderer.h"
#include "engine/scene/scene_loader.h"
#include "tests/gpu/gpu_test.h"
#include "tests/support/scene_builder.h"
#include "tests/support/vpl_render.h"

namespace mvpl::render {
namespace {

// A torus around the y axis: major radius R, minor r, nu × nv quads of two triangles (nu · nv · 2
// triangles), its winding flipped when `flip`.
scene::Mesh make_torus(const Vec3& centre, float major, float minor, int nu, int nv, bool flip) {
    scene::Mesh mesh;
    for (int i = 0; i < nu; ++i) {
        const float u = 2.0f * kPi * float(i) / float(nu);
        for (int j = 0; j < nv; ++j) {
            const float v = 2.0f * kPi * float(j) / float(nv);
            const Vec3 ring(std::cos(u), 0.0f, std::sin(u));
            const Vec3 n = std::cos(v) * ring + Vec3(0.0f, std::sin(v), 0.0f);
            mesh.positions.push_back(centre + major * ring + minor * n);
            mesh.normals.push_back(n);
        }
    }
    auto at = [&](int i, int j) { return uint32_t((i % nu) * nv + (j % nv)); };
    for (int i = 0; i < nu; ++i) {
        for (int j = 0; j < nv; ++j) {
            const uint32_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
            for (const uint32_t t : {a, b, c, a, c, d})
                mesh.indices.push_back(t);
        }
    }
    if (flip) {
        for (size_t t = 0; t < mesh.indices.size(); t += 3)
            std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
    }
    return mesh;
}

// The torus wound outwards (whichever of the two windings bounds a solid).
scene::Mesh solid_torus(const Vec3& centre, float major, float minor) {
    scene::Mesh torus = make_torus(centre, major, minor, 96, 32, false);
    if (!bounds_solid(torus.positions, torus.indices))
        torus = make_torus(centre, major, minor, 96, 32, true);
    return torus;
}

TEST(ClosedSurface, ClosedOutwardMeshesBoundASolid) {
    const scene::Mesh sphere = test::make_icosphere(Vec3(1.0f), 0.5f, 3, false, 0);
    EXPECT_TRUE(bounds_solid(sphere.positions, sphere.indices));
    // Wound inwards: closed, but the solid would be everything outside it.
    const scene::Mesh inward = test::make_icosphere(Vec3(1.0f), 0.5f, 3, true, 0);
    EXPECT_FALSE(bounds_solid(inward.positions, inward.indices));
    // One triangle missing: open.
    std::vector<uint32_t> open(sphere.indices.begin() + 3, sphere.indices.end());
    EXPECT_FALSE(bounds_solid(sphere.positions, open));
    // One triangle flipped: not consistently wound.
    std::vector<uint32_t> flipped = sphere.indices;
    std::swap(flipped[1], flipped[2]);
    EXPECT_FALSE(bounds_solid(sphere.positions, flipped));
    // A triangle twice: an edge with four triangles.
    std::vector<uint32_t> doubled = sphere.indices;
    doubled.insert(doubled.end(), sphere.indices.begin(), sphere.indices.begin() + 3);
    EXPECT_FALSE(bounds_solid(sphere.positions, doubled));
    // A concave solid: exactly one of the torus's two windings bounds it.
    const scene::Mesh a = make_torus(Vec3(0.0f), 1.0f, 0.3f, 24, 12, false);
    const scene::Mesh b = make_torus(Vec3(0.0f), 1.0f, 0.3f, 24, 12, true);
    EXPECT_NE(bounds_solid(a.positions, a.indices), bounds_solid(b.positions, b.indices));
    // A plane (the Cornell box's walls are open quads).
    const scene::Mesh quad = test::make_quad(Vec3(0.0f), Vec3(1, 0, 0), Vec3(0, 0, 1), 0);
    EXPECT_FALSE(bounds_solid(quad.positions, quad.indices));
}

// A double-sided material: only a solid's closedness lets the G-buffer cull its back faces.
int add_double_sided(scene::Scene& s) {
    scene::Material m = test::diffuse_material(Rgb(0.6f));
    m.double_sided = true;
    s.materials.push_back(m);
    return int(s.materials.size()) - 1;
}

// The Cornell box with a dense, double-sided torus (6144 triangles) standing on its floor.
scene::Scene box_with_torus() {
    scene::Scene s = scene::load_scene(MVPL_ASSETS_DIR "/cornell-box/cbox.gltf");
    const scene::Bounds b = s.bounds();
    const Vec3 extent = b.hi - b.lo;
    const float size = std::min({extent.x, extent.y, extent.z});
    s.meshes.push_back(
        solid_torus(b.lo + Vec3(0.5f, 0.0f, 0.5f) * extent + Vec3(0.0f, 0.12f * size, 0.0f),
                    0.25f * size, 0.1f * size));
    s.meshes.back().material = add_double_sided(s);
    return s;
}

TEST(SolidCulling, OnlyVplsOutsideTheSolidsBoxDrawFrontFacesOnly) {
    const scene::Scene s = box_with_torus();
    const ShadowClusters clusters(s);
    ASSERT_EQ(clusters.groups().size(), 2u);  // the torus, then the box's walls
    const ShadowGroup& torus = clusters.groups().front();
    EXPECT_TRUE(torus.solid);
    EXPECT_FALSE(clusters.groups().back().solid);
    CasterRanges ranges;
    const Vec3 above(torus.centre.x, torus.solid_hi.y * 1.5f, torus.centre.z);
    clusters.visible_ranges(above, 3, nullptr, 0.0f, LodChoice{}, ranges);  // looking down
    EXPECT_FALSE(ranges.by_kind[CasterRanges::kFrontOnly].empty());
    // In the torus's hole: inside its box, though outside the solid.
    clusters.visible_ranges(torus.centre, 3, nullptr, 0.0f, LodChoice{}, ranges);
    EXPECT_TRUE(ranges.by_kind[CasterRanges::kFrontOnly].empty());
    EXPECT_FALSE(ranges.full().empty());
    // Directional VPLs are outside every solid.
    clusters.level_ranges(torus.centre, LodChoice{}, ranges, true);
    EXPECT_FALSE(ranges.by_kind[CasterRanges::kFrontOnly].empty());
}

using SolidCullingTest = gpu::testing::GpuTest;

// Renders `vpls` with back-face culling on and off: the same image (but for silhouette ties,
// below), and culling did happen.
void expect_same_image(gpu::Context& context, const scene::Scene& s, const light::VplSet& vpls) {
    VplRenderer renderer(context, s);
    RenderOptions o;
    o.width = o.height = 64;
    for (const uint32_t shadow_res : {32u, 128u}) {
        o.shadow_resolution = shadow_res;
        o.backface_culling = true;
        RenderTimings culled;
        const Image with = renderer.render(vpls, o, &culled);
        o.backface_culling = false;
        RenderTimings both;
        const Image without = renderer.render(vpls, o, &both);
        EXPECT_GT(culled.shadow_front_only_triangles, 0u);
        EXPECT_EQ(both.shadow_front_only_triangles, 0u);
        // The double-sided solids in the G-buffer too (one-sided materials are culled anyway).
        EXPECT_GT(culled.g_buffer_front_only_triangles, both.g_buffer_front_only_triangles);
        EXPECT_EQ(culled.shadow_triangles, both.shadow_triangles);
        // Culling leaves every texel's distance as it was. Where a texel's centre falls on a
        // silhouette's fold, the front and the back face there tie within rounding and the
        // texel keeps either face's plane (shaders/shared/shadow_map.h) when both are drawn, so
        // a pixel whose lookup that texel decides (occluder_plane_passes_behind) may take the
        // other answer for that one VPL: at most a few pixels, and the image's mean within one
        // VPL's share of a few pixels.
        size_t differing = 0;
        for (size_t i = 0; i < with.pixels().size(); ++i)
            differing += with.pixels()[i] != without.pixels()[i] ? 1 : 0;
        EXPECT_LE(differing, with.pixels().size() / 1000) << "shadow faces " << shadow_res;
        EXPECT_NEAR(with.mean().r, without.mean().r, 1e-3f * without.mean().r);
        EXPECT_GT(with.mean().r, 0.0f);
    }
}

// What the maps hold where they see a sphere of radius 1 head on: its near side, not its far
// side (which the wrong winding for "front" would leave): 2 from a point VPL at distance 3 from
// its centre, and 2 along the direction of travel from a directional VPL's near plane to it.
TEST_F(SolidCullingTest, TheMapsHoldTheSolidsNearSide) {
    scene::Scene s;
    s.materials = {test::diffuse_material(Rgb(0.5f))};
    s.meshes = {test::make_icosphere(Vec3(0.0f), 1.0f, 5, false, 0)};
    const SceneGeometry geometry(context(), s);
    const ShadowClusters clusters(s);
    ASSERT_TRUE(clusters.groups().front().solid);
    ShadowPassOptions options;
    options.resolution = 16;
    options.max_batch = 2;
    options.lod = false;  // full triangles, distances not negated
    for (const bool culled : {true, false}) {
        options.front_faces = culled;
        ShadowPass pass(context(), geometry, clusters, options);
        light::Vpl point;
        point.type = light::VplType::Point;
        point.position = Vec3(0.0f, 0.0f, 3.0f);
        light::Vpl sun;
        sun.type = light::VplType::Directional;
        sun.normal = Vec3(0.0f, 0.0f, -1.0f);
        const std::vector<light::Vpl> batch{point, sun};
        context().submit_and_wait([&](gpu::CommandList& cmd) { pass.record(cmd, batch); });
        EXPECT_EQ(pass.front_only_triangles() > 0, culled);
        // Cube 0, face −Z (5), texel (8, 8): its centre ray leaves the VPL along
        // (±1/16, ±1/16, −1) and meets the sphere at d = 3 cos θ ∓ √(1 − 9 sin² θ), the near
        // side at 2.024, the far side at 3.95 (the icosphere's flat triangles lie up to
        // 2.4·10⁻⁴ inside the sphere).
        const float cos_t = 1.0f / std::sqrt(1.0f + 2.0f / 256.0f);
        const float sin2 = 1.0f - cos_t * cos_t;
        const float near = 3.0f * cos_t - std::sqrt(1.0f - 9.0f * sin2);
        // Two floats a texel (shadow_texel.h): the distance first.
        const std::vector<float> face = pass.cubes().download_as<float>(5, 1);
        EXPECT_NEAR(face[2 * (8 * 16 + 8)], near, 2e-3f) << (culled ? "culled" : "both faces");
        // The directional map's texel (8, 8): its centre lies (u, v) off the sphere's centre,
        // where the near side is √(1 − u² − v²) before it along the direction of travel.
        const DirectionalFrame f = directional_frame(sun.normal, s.bounds());
        const float off = 8.5f / 16.0f * f.extent + f.origin.x;  // origin.x = origin.y here
        const float expected = -std::sqrt(1.0f - 2.0f * off * off) - f.origin.z;
        const std::vector<float> map = pass.ortho_maps().download_as<float>(1, 1);
        EXPECT_NEAR(map[2 * (8 * 16 + 8)], expected, 2e-3f) << (culled ? "culled" : "both faces");
    }
}

// Cube faces: the area light above the torus sees it from outside; the surface VPLs on it and
// in its hole from inside its box (both faces).
TEST_F(SolidCullingTest, CubeFacesAreTheSameWithBackFacesCulled) {
    const scene::Scene s = box_with_torus();
    expect_same_image(context(), s, test::monte_carlo_vpls(s, 64, 4, 3));
}

// Orthographic maps: a torus and a sphere on a floor under a directional light.
TEST_F(SolidCullingTest, OrthographicMapsAreTheSameWithBackFacesCulled) {
    scene::Scene s =
        test::floor_under_sun({solid_torus(Vec3(-0.5f, 0.35f, 0.0f), 1.0f, 0.3f),
                               test::make_icosphere(Vec3(1.2f, 0.5f, 1.0f), 0.5f, 5, false, 0)});
    s.meshes[1].material = s.meshes[2].material = add_double_sided(s);
    expect_same_image(context(), s, test::monte_carlo_vpls(s, 32, 3, 5));
}

}  // namespace
}  // namespace mvpl::render
