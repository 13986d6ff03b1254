// Shadow maps kept across begin() (render/kept_shadow_maps.h, the preview's camera moves): the
// image shaded at a new view with kept maps equals the image of a renderer that draws every map
// afresh, on scenes whose maps differ in kind (area and surface VPLs with hemicubes, thin walls
// between two rooms, a closed box seen from inside, a sun's orthographic maps), at two scales,
// interleaved or not, with VPL culling (VPLs culled at the first view have no kept map), and
// within a budget that holds only some of the cubes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/light/light_sampler.h"
#include "engine/render/kept_shadow_maps.h"
#include "engine/render/vpl_renderer.h"
#include "engine/sampler/monte_carlo_sampler.h"
#include "engine/scene/camera.h"
#include "engine/scene/scene_loader.h"
#include "engine/trace/accel.h"
#include "tests/gpu/gpu_test.h"
#include "tests/support/scene_builder.h"

namespace mvpl::render {
namespace {

using KeptShadowMapsTest = gpu::testing::GpuTest;

struct Case {
    std::string name;
    std::string scene;
    float scale = 1.0f;  // applied to every vertex, light and camera
    uint32_t interleave = 1;
};

struct Loaded {
    scene::Scene scene;
    light::VplSet set;
};

Loaded load(const Case& c, uint64_t seed) {
    Loaded l{scene::load_scene(MVPL_ASSETS_DIR "/" + c.scene), {}};
    if (c.scale != 1.0f) test::scale_scene(l.scene, c.scale);
    const trace::Accel accel(l.scene);
    const light::LightSampler lights(l.scene);
    sampler::MonteCarloOptions o;
    o.paths = 32;
    o.seed = seed;
    l.set = sampler::MonteCarloSampler(l.scene, accel, lights).generate(o);
    return l;
}

// The scene camera turned 25° about the vertical through the middle of the scene's box: part of
// what it sees was outside the first view (VPLs culled there light it now).
scene::Camera moved_camera(const scene::Scene& s) {
    const Vec3 centre = s.bounds().center();
    const Vec3 eye = s.camera.position();
    const float a = glm::radians(25.0f);
    const Vec3 d = eye - centre;
    const Vec3 turned(d.x * std::cos(a) + d.z * std::sin(a), d.y,
                      -d.x * std::sin(a) + d.z * std::cos(a));
    return scene::look_at_camera(centre + turned, centre, Vec3(0.0f, 1.0f, 0.0f), s.camera.yfov,
                                 s.camera.znear);
}

RenderOptions options(const Case& c, uint64_t kept_bytes) {
    RenderOptions o;
    o.width = o.height = 40;
    o.shadow_resolution = 64;
    o.batch = 8;
    o.interleave = c.interleave;
    o.kept_shadow_bytes = kept_bytes;
    return o;
}

// Kept maps are copies of the maps drawn: the same image to the bit.
void expect_identical(const Image& a, const Image& b) {
    ASSERT_EQ(a.pixels().size(), b.pixels().size());
    size_t differing = 0;
    for (size_t i = 0; i < a.pixels().size(); ++i)
        differing += a.pixels()[i] != b.pixels()[i];
    EXPECT_EQ(differing, 0u);
}

// VPLs whose map is that of an earlier VPL of the set (kept_shadow_maps.h's key).
size_t repeats(const std::vector<light::Vpl>& vpls) {
    const auto same_map = [](const light::Vpl& a, const light::Vpl& b) {
        return a.type == b.type && a.position == b.position && a.normal == b.normal &&
               a.path_length == b.path_length;
    };
    size_t n = 0;
    for (size_t i = 0; i < vpls.size(); ++i)
        n += std::any_of(vpls.begin(), vpls.begin() + std::ptrdiff_t(i),
                         [&](const light::Vpl& v) { return same_map(v, vpls[i]); });
    return n;
}

class KeptAcrossAMove : public KeptShadowMapsTest, public ::testing::WithParamInterface<Case> {};

TEST_P(KeptAcrossAMove, TheNewViewEqualsFreshlyDrawnMaps) {
    const Case c = GetParam();
    const Loaded l = load(c, 5);
    const scene::Camera moved = moved_camera(l.scene);
    const double scale = l.set.scale;

    VplRenderer fresh(context(), l.scene);
    fresh.begin(moved, options(c, 0));
    fresh.accumulate(l.set.vpls);
    const Image expected = fresh.resolve(scale);
    const uint64_t culled_at_new_view = fresh.timings().culled_vpls;

    VplRenderer kept(context(), l.scene);
    kept.begin(l.scene.camera, options(c, kDefaultKeptBytes));
    kept.accumulate(l.set.vpls);
    kept.resolve(scale);
    // Within the first estimate only a VPL equal to one of an earlier batch finds its map (a
    // sun's VPLs all share one orthographic map).
    EXPECT_LE(kept.timings().kept_maps, repeats(l.set.vpls));
    const uint64_t culled_at_first_view = kept.timings().culled_vpls;
    kept.begin(moved, options(c, kDefaultKeptBytes));
    kept.accumulate(l.set.vpls);
    expect_identical(kept.resolve(scale), expected);
    // Every VPL shaded at the new view that was drawn at the first had its map copied back.
    const uint64_t shaded = l.set.vpls.size() - culled_at_new_view;
    EXPECT_GE(kept.timings().kept_maps, shaded - culled_at_first_view);
    EXPECT_LE(kept.timings().kept_maps, shaded);
    EXPECT_GT(kept.timings().kept_maps, 0u);
    EXPECT_LT(kept.timings().shadow_texels, fresh.timings().shadow_texels);
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, KeptAcrossAMove,
    ::testing::Values(Case{"CornellBox", "cornell-box/cbox.gltf"},
                      Case{"CornellBoxTinyInterleaved", "cornell-box/cbox.gltf", 1e-3f, 2},
                      Case{"TwoRooms", "two-room/two-room.gltf"},
                      Case{"TwoRoomsHugeInterleaved", "two-room/two-room.gltf", 1e3f, 2},
                      Case{"GlossyUnderTheSun", "glossy/glossy.gltf"}),
    [](const ::testing::TestParamInfo<Case>& info) { return info.param.name; });

// A budget of five cubes: replaying the same VPLs keeps the first five (a cube used in the
// current estimate is never evicted), and a new set of VPLs (another seed: a new Metropolis
// chain) takes the places of the old set's cubes in its first estimate and finds them in its
// second. The images stay those of freshly drawn cubes.
TEST_F(KeptShadowMapsTest, ABudgetKeepsTheFirstCubesAndNewVplsEvictOldOnes) {
    const Case c{"CornellBox", "cornell-box/cbox.gltf"};
    const Loaded first = load(c, 5), second = load(c, 6);
    // The shadow pass gives the cubes 6/7 of the budget (and the orthographic maps the rest).
    const uint64_t budget = 5 * KeptShadowMaps::map_bytes(false, 64) * 7 / 6 + 100;
    RenderOptions o = options(c, budget);
    o.vpl_culling = false;  // every VPL drawn: the counts below are exact
    VplRenderer kept(context(), first.scene);
    for (int estimate = 0; estimate < 2; ++estimate) {
        kept.begin(first.scene.camera, o);
        kept.accumulate(first.set.vpls);
        kept.resolve(first.set.scale);
        EXPECT_EQ(kept.timings().kept_maps, estimate == 0 ? 0u : 5u);
    }
    for (int estimate = 0; estimate < 2; ++estimate) {
        kept.begin(first.scene.camera, o);
        kept.accumulate(second.set.vpls);
        const Image image = kept.resolve(second.set.scale);
        EXPECT_EQ(kept.timings().kept_maps, estimate == 0 ? 0u : 5u);
        if (estimate == 1) {
            VplRenderer fresh(context(), first.scene);
            o.kept_shadow_bytes = 0;
            expect_identical(image, fresh.render(second.set, o));
        }
    }
}

}  // namespace
}  // namespace mvpl::render
