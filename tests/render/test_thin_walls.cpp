// Issue 13, item 3: a zero-thickness wall, double-sided or one-sided, must shadow as exact
// visibility does, along the lines where it meets the floor and the back wall too (issue 32: at
// every shadow resolution and wall position against the texel grid, not only the first one). A
// thick wall hides the one-texel band on its far side where a shadow-map test is unsure; a single
// plane leaves that band in view, and a test that leaks there draws bright lines along its
// junctions.
#include <gtest/gtest.h>

#include <array>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "engine/core/image.h"
#include "engine/core/image_metrics.h"
#include "engine/gpu/context.h"
#include "engine/render/directional_frame.h"
#include "engine/render/vpl_renderer.h"
#include "tests/gpu/gpu_test.h"
#include "tests/render/render_test_util.h"
#include "tests/support/scene_builder.h"
#include "tests/support/vpl_render.h"

namespace mvpl::render {
namespace {

using ThinWallTest = gpu::testing::GpuTest;

constexpr int kWallSize = 128;
constexpr float kHeight = 2.5f;
constexpr int kWallMesh = 3;

// One member of the family: the scene's scale, the wall's sides, the shadow faces' side and where
// the wall stands (x), which moves its junctions against the texel grid.
struct WallCase {
    float scale = 1.0f;
    bool double_sided = true;
    uint32_t shadow_resolution = 64;
    float wall_x = 0.0f;
};

void PrintTo(const WallCase& c, std::ostream* os) {
    *os << "scale " << c.scale << (c.double_sided ? ", double-sided, " : ", one-sided, ")
        << c.shadow_resolution << "² faces, wall at x = " << c.wall_x;
}

// A floor (y = 0), a back wall (z = −2) and a ceiling (y = kHeight), x and z in [−2, 2], and a
// single plane at x = wall_x (facing +x) that runs from floor to ceiling and from the back wall to
// the floor's front edge: junctions without a crack and no free edge whose shadow could fall on the
// floor, so that every receiver on one side of the wall is dark for a VPL on the other, exactly.
// The camera stands in front of the wall's end and sees both sides. Without `ceiling` its mesh is
// left empty (for a directional VPL from above) and the wall is taller.
scene::Scene thin_wall_scene(const WallCase& c, bool ceiling = true) {
    scene::Scene s;
    s.materials = {test::diffuse_material(Rgb(0.6f, 0.6f, 0.55f)),
                   test::diffuse_material(Rgb(0.3f, 0.5f, 0.7f))};
    s.materials[1].double_sided = c.double_sided;
    s.meshes.push_back(test::make_quad(Vec3(-2, 0, -2), Vec3(0, 0, 4), Vec3(4, 0, 0), 0));
    s.meshes.push_back(test::make_quad(Vec3(-2, 0, -2), Vec3(4, 0, 0), Vec3(0, kHeight, 0), 0));
    s.meshes.push_back(test::make_quad(Vec3(-2, kHeight, -2), Vec3(4, 0, 0), Vec3(0, 0, 4), 0));
    if (!ceiling) s.meshes.back() = scene::Mesh{};
    // Without the ceiling the wall rises to 3 kHeight, so that its top edge shades nothing the
    // camera sees.
    const float wall = ceiling ? kHeight : 3.0f * kHeight;
    s.meshes.push_back(test::make_quad(Vec3(c.wall_x, 0, -2), Vec3(0, wall, 0), Vec3(0, 0, 4), 1));
    s.camera = test::look_at(Vec3(0.03f, 1.3f, 3.4f), Vec3(-0.05f, 0.45f, -0.9f), 0.75f);
    s.has_camera = true;
    return s;
}

// A point VPL and a surface VPL on the back wall that lights the floor at grazing angles, both at
// x < 0, a point VPL at x > 0, and a directional VPL from the x < 0 side.
std::vector<light::Vpl> thin_wall_vpls() {
    light::Vpl point;
    point.type = light::VplType::Point;
    point.position = Vec3(-0.9f, 0.8f, 0.35f);
    point.power = Rgb(3.0f);
    light::Vpl surface;
    surface.type = light::VplType::Surface;
    surface.position = Vec3(-1.2f, 0.25f, -1.999f);
    surface.normal = surface.shading_normal = Vec3(0, 0, 1);
    surface.wi = glm::normalize(Vec3(0.2f, 0.3f, 1.0f));
    surface.closure = material::ClosureParams{};
    surface.power = Rgb(2.0f);
    light::Vpl other_side = point;
    other_side.position = Vec3(1.1f, 1.9f, -0.6f);
    // Travelling towards +x, down and back (the ceiling is left out for it: it would shade
    // everything): the x > 0 side in the wall's shadow.
    light::Vpl sun;
    sun.type = light::VplType::Directional;
    sun.normal = glm::normalize(Vec3(1.0f, -0.7f, -0.4f));
    sun.power = Rgb(1.5f);
    return {point, surface, other_side, sun};
}

RenderOptions thin_wall_options(uint32_t shadow_resolution) {
    RenderOptions options;
    options.width = options.height = kWallSize;
    options.shadow_resolution = shadow_resolution;
    options.clamp = 0.0f;
    options.jitter = false;
    return options;
}

struct Classified {
    int shadowed = 0;        // exact and GPU agree: black
    int lit = 0;             // exact and GPU agree: lit
    int junction = 0;        // of the shadowed, those within 5 cm of the wall
    int misclassified = 0;   // all of them in a band (asserted)
    int darkened = 0;        // of those, lit pixels farther than rounding from every occluder plane
    int in_band = 0;         // pixels that a band lets differ
    float worst_lit = 0.0f;  // largest error of a lit pixel
    float brightest = 0.0f;  // largest expected value
};

// The planes that meet at the junctions, as (unit normal, offset): floor, back wall, ceiling,
// thin wall.
std::array<std::pair<Vec3, float>, 4> planes(float wall_x) {
    return {{{Vec3(0, 1, 0), 0.0f},
             {Vec3(0, 0, 1), -2.0f},
             {Vec3(0, 1, 0), kHeight},
             {Vec3(1, 0, 0), wall_x}}};
}

// Where the shadow map may legitimately disagree with exact visibility at receiver p (geometric
// normal n, facing the VPL) because an occluder's plane passes close to it; the two lookups of
// shadow_lookup.glsl's visibility(), τ the texel angle, d the distance:
// - the junction lookup reads the texel of p' = p + τ·d·sin θ·n (the normal offset) and compares
//   p''s own distance with what the texel stores along its centre, up to half a texel diagonal
//   (0.71 τ) from p' as seen from the VPL. On an occluder plane met at angle β from its normal,
//   that lateral error moves the stored distance by up to 0.71 τ d tan β along the ray: within
//   0.71 τ d sin β of the plane (along its normal) p' may land on either side. That is the only
//   band where light may leak, and it may darken there too.
// - the receiver-plane lookup reads the texel of p, whose centre meets p's plane up to
//   0.71 τ d / cos θ from p: an occluder plane within that distance may cut in between (a
//   concave corner seen at a grazing angle). The texel's own plane then says whether it stands
//   before p or beyond it, so a lit p is no longer darkened there (Classified::darkened).
// 0.75 for 0.71 covers float rounding.
struct Band {
    bool may_leak = false;
    bool may_darken = false;
};

// A directional VPL's orthographic map has the same bands with parallel rays, a texel's width
// (extent / resolution) in place of τ·d.
struct LightGeometry {
    Vec3 to_light;    // unit, from the receiver
    float footprint;  // τ·d, or a texel's width
};

LightGeometry light_geometry(const light::Vpl& vpl, const Vec3& p, float tau, float texel) {
    if (vpl.type == light::VplType::Directional) return {-vpl.normal, texel};
    const Vec3 r = vpl.position - p;
    return {glm::normalize(r), tau * glm::length(r)};
}

// A point beyond the light along the receiver's shadow ray (exact visibility's segment end).
Vec3 light_point(const light::Vpl& vpl, const Vec3& p) {
    return vpl.type == light::VplType::Directional ? p - 100.0f * vpl.normal : vpl.position;
}

Band junction_band(const Vec3& p, const Vec3& n, const light::Vpl& vpl, float tau, float texel,
                   float wall_x) {
    const LightGeometry g = light_geometry(vpl, p, tau, texel);
    const float cos_theta = glm::dot(n, g.to_light);
    const float sin_theta = std::sqrt(std::max(0.0f, 1.0f - cos_theta * cos_theta));
    const Vec3 lookup = p + n * (g.footprint * sin_theta);
    const LightGeometry moved = light_geometry(vpl, lookup, tau, texel);
    Band band;
    for (const auto& [normal, offset] : planes(wall_x)) {
        if (std::abs(glm::dot(normal, n)) > 0.999f) continue;  // the receiver's own plane
        const float cos_beta = glm::dot(normal, moved.to_light);
        const float sin_beta = std::sqrt(std::max(0.0f, 1.0f - cos_beta * cos_beta));
        if (std::abs(glm::dot(normal, lookup) - offset) < 0.75f * moved.footprint * sin_beta)
            band.may_leak = band.may_darken = true;
        if (std::abs(glm::dot(normal, p) - offset) < 0.75f * g.footprint / cos_theta)
            band.may_darken = true;
    }
    return band;
}

// Whether p lies within rounding of an occluder plane: twice the shadow test's constant bias
// (2·10⁻⁴ of the distance, shadow_lookup.glsl; for a directional VPL of the depth from its map's
// near plane, at most the scene's diagonal) from a plane other than its own.
bool at_junction(const Vec3& p, const Vec3& n, const light::Vpl& vpl, float wall_x,
                 float diagonal) {
    const float d =
        vpl.type == light::VplType::Directional ? diagonal : glm::length(vpl.position - p);
    for (const auto& [normal, offset] : planes(wall_x)) {
        if (std::abs(glm::dot(normal, n)) > 0.999f) continue;
        if (std::abs(glm::dot(normal, p) - offset) < 4e-4f * d) return true;
    }
    return false;
}

// Every floor, back-wall and ceiling pixel against exact visibility (a segment test against the
// wall): a misclassified pixel must lie in the band (junction_band) that allows its error.
Classified classify(const scene::Scene& scene, const Image& image, const light::Vpl& vpl, float tau,
                    float texel, float wall_x) {
    Classified c;
    const float diagonal = scene.bounds().diagonal();
    for (int y = 0; y < kWallSize; ++y) {
        for (int x = 0; x < kWallSize; ++x) {
            const std::optional<testing::CpuHit> hit =
                testing::cast_camera_ray(scene, kWallSize, kWallSize, x, y);
            if (!hit || hit->mesh == kWallMesh) continue;
            const Rgb expected = testing::cpu_contribution(vpl, hit->p, hit->ng,
                                                           testing::closure_of(scene.materials[0]),
                                                           scene.camera.position(), 0.0f);
            if (max_component(expected) <= 0.0f) continue;
            const bool in_shadow = testing::segment_hits_mesh(scene.meshes[kWallMesh], hit->p,
                                                              light_point(vpl, hit->p));
            const Band band = junction_band(hit->p, hit->ng, vpl, tau, texel, wall_x);
            const bool may_differ = in_shadow ? band.may_leak : band.may_darken;
            c.in_band += may_differ;
            const Rgb got = image.at(x, y);
            const bool gpu_shadow = got == Rgb(0.0f);
            if (gpu_shadow != in_shadow) {
                ++c.misclassified;
                EXPECT_TRUE(may_differ)
                    << "pixel " << x << "," << y << " at (" << hit->p.x << ", " << hit->p.y << ", "
                    << hit->p.z << ") " << (in_shadow ? "leaks" : "falsely shadowed");
                if (!in_shadow && !at_junction(hit->p, hit->ng, vpl, wall_x, diagonal))
                    ++c.darkened;
                continue;
            }
            if (in_shadow) {
                ++c.shadowed;
                c.junction += std::abs(hit->p.x - wall_x) < 0.05f;
            } else {
                ++c.lit;
                c.worst_lit = std::max(c.worst_lit, max_component(glm::abs(got - expected)));
                c.brightest = std::max(c.brightest, max_component(expected));
            }
        }
    }
    return c;
}

class ThinWallFamily : public ThinWallTest, public ::testing::WithParamInterface<WallCase> {};

TEST_P(ThinWallFamily, AZeroThicknessWallShadowsUpToItsJunctions) {
    const WallCase wc = GetParam();
    std::vector<light::Vpl> vpls = thin_wall_vpls();
    for (size_t i = 0; i < vpls.size(); ++i) {
        SCOPED_TRACE("VPL " + std::to_string(i));
        const bool ceiling = vpls[i].type != light::VplType::Directional;
        scene::Scene scene = thin_wall_scene(wc, ceiling);
        test::scale_scene(scene, wc.scale);
        VplRenderer renderer(context(), scene);
        light::Vpl vpl = vpls[i];
        vpl.position *= wc.scale;
        // The same irradiance at s times the distance; a directional VPL's does not depend on it.
        if (vpl.type != light::VplType::Directional) vpl.power *= wc.scale * wc.scale;
        const Image image = renderer.render({{vpl}}, thin_wall_options(wc.shadow_resolution));
        // Classified in the unit scene: the image must not depend on the scale.
        const scene::Scene unit = thin_wall_scene(wc, ceiling);
        const float res = float(wc.shadow_resolution);
        const float texel = directional_frame(vpls[i].normal, unit.bounds()).extent / res;
        const Classified c = classify(unit, image, vpls[i], 2.0f / res, texel, wc.wall_x);
        EXPECT_GT(c.shadowed, 200);
        EXPECT_GT(c.junction, 10);
        EXPECT_GT(c.lit, 500);
        // Lit pixels carry the unshadowed value: float rounding only (relative to the brightest,
        // since a grazing pixel's value is a difference of nearly equal cosines at 10⁴ scale).
        EXPECT_LT(c.worst_lit, 1e-3f * c.brightest);
        // A shadow texel holds its surface's plane (shaders/shared/shadow_map.h), so a wall or
        // floor that meets the receiver in a concave corner does not darken it: only a lit pixel
        // within rounding of an occluder plane may come out black (before the plane, up to 2 024
        // pixels for the surface VPL that lights the floor at grazing angles).
        EXPECT_EQ(c.darkened, 0);
        RecordProperty("misclassified_" + std::to_string(i), c.misclassified);
        RecordProperty("in_band_" + std::to_string(i), c.in_band);
    }
}

// Scales 10⁻³, 1 and 10⁴; both kinds of wall; shadow faces of 64², 256² and 1024²; the wall at
// x = 0 and moved off the grid by an irrational-looking fraction of a texel.
std::vector<WallCase> wall_family() {
    std::vector<WallCase> cases;
    for (const float scale : {1.0f, 1e-3f, 1e4f}) {
        for (const bool double_sided : {true, false}) {
            for (const uint32_t res : {64u, 256u, 1024u}) {
                const float wall_x = res == 64u ? 0.0f : res == 256u ? -0.0137f : 0.0071f;
                cases.push_back({scale, double_sided, res, wall_x});
            }
        }
    }
    return cases;
}

INSTANTIATE_TEST_SUITE_P(Family, ThinWallFamily, ::testing::ValuesIn(wall_family()));

// The two rooms the wall divides, lit by a point light on one side, with the light paths' VPLs
// on both sides: the GPU against the oracle over the same VPLs, at image sizes 64² and 128² and
// shadow faces 128² and 256² (256² images held too, docs/results.md; the oracle's cost keeps them
// out of CI). Leaks along the junctions brightened the other room's mean by 2.2 %
// (issue 32); what the shadow maps may still differ by is their texel-wide band at every shadow
// edge, under 0.5 % of the mean here (the Cornell box's is 0.1 %: test_vpl_pipeline.cpp).
TEST_F(ThinWallTest, TwoRoomsMeanMatchesTheOracle) {
    for (const bool double_sided : {true, false}) {
        scene::Scene s = thin_wall_scene({1.0f, double_sided, 64, -0.0137f});
        scene::Light light;
        light.type = scene::LightType::Point;
        light.intensity = Rgb(6.0f);
        light.position = Vec3(-1.1f, 1.7f, 0.4f);
        s.lights = {light};
        const light::VplSet vpls = test::monte_carlo_vpls(s, 256, 6, 7);
        for (const auto& [res, shadow_res] : {std::pair{64, 128}, {128, 256}}) {
            SCOPED_TRACE(std::string(double_sided ? "double" : "one") + "-sided, image " +
                         std::to_string(res) + "², faces " + std::to_string(shadow_res) + "²");
            const test::VplRenderSettings settings{
                .res = res, .shadow_res = shadow_res, .clamp = 0.05f};
            const Image oracle = test::oracle_render(s, vpls, settings);
            const ImageError e =
                compare_images(test::gpu_render(context(), s, vpls, settings), oracle);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(e.mean_ratio[c], 1.0, 0.005) << "channel " << c;
        }
    }
}

}  // namespace
}  // namespace mvpl::render
