// Interleaved sampling with specular chains (issues 14/15; shaders/shared/interleave.h,
// "Chains"): a chained pixel is filtered only with chained neighbours whose rough ends are
// compatible and weighted by its own throughput. The GPU equals the oracle, which reproduces the
// assignment, the chains and the filter, within the shadow-map bound; and the filter never
// mixes a chained pixel with an unchained one, on a plane where the G-buffer alone would let it.
#include <gtest/gtest.h>

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/image.h"
#include "engine/core/image_metrics.h"
#include "engine/light/light_sampler.h"
#include "engine/light/specular_chain.h"
#include "engine/scene/camera.h"
#include "engine/trace/accel.h"
#include "engine/trace/interaction.h"
#include "tests/gpu/gpu_test.h"
#include "tests/support/mirror_box.h"
#include "tests/support/scene_builder.h"
#include "tests/support/vpl_render.h"

namespace mvpl::render {
namespace {

using InterleaveChainsTest = gpu::testing::GpuTest;

// The mirror sphere of test_specular_chains with K = 2. The bound is that test's (and
// test_interleave's Cornell box test's): GPU and oracle differ only where the shadow cube's
// nearest texel decides visibility differently from Embree, a band of 1.25 texel angles of 2/res
// each, relMSE ≤ 1.25 · 2/res; the chains are the same paths on both sides (light::chain_rng), and
// the filter reads the same chain records (both computed on the CPU), so its decisions agree.
TEST_F(InterleaveChainsTest, TheGpuEqualsTheOracleOnAMirrorSphere) {
    const scene::Scene s = test::make_mirror_box();
    const light::VplSet vpls = test::monte_carlo_vpls(s, 256, 4, 5);
    test::VplRenderSettings settings{.res = 48, .shadow_res = 256, .clamp = 0.05f};
    settings.chain_roughness = light::kDefaultChainRoughness;
    settings.chain_max_depth = 4;
    settings.chain_seed = 9;
    settings.interleave = 2;
    const Image oracle = test::oracle_render(s, vpls, settings);
    const Image gpu = test::gpu_render(context(), s, vpls, settings);
    const double bound = 1.25 * 2.0 / 256.0;
    const double error = compare_images(gpu, oracle).rel_mse;
    EXPECT_LT(error, bound);
    RecordProperty("relmse", std::to_string(error));
    std::printf("GPU vs oracle, chains and K = 2: relMSE %.3g (bound %.3g)\n", error, bound);

    // Interleaving is applied: the image is another estimate than K = 1's (which it was before
    // the two were combined).
    test::VplRenderSettings plain = settings;
    plain.interleave = 1;
    const double change = compare_images(test::oracle_render(s, vpls, plain), oracle).rel_mse;
    EXPECT_GT(change, 1e-6);
    RecordProperty("relmse_k1_vs_k2", std::to_string(change));
    std::printf("oracle K = 1 vs K = 2: relMSE %.3g\n", change);
}

// A glossy plastic floor (base 0.1, roughness 0.05) seen from above: its specular lobe carries
// at least half of what it reflects beyond about 63° from the normal (Bsdf::
// specular_probability), so the far part of the floor is chained and the near part is not —
// one plane, one material, one colour, which the G-buffer's test accepts across the boundary.
// The chains end on a white back wall. No emitters: the image is VPL light only.
constexpr int kFloor = 0;

scene::Scene floor_and_wall() {
    scene::Scene s;
    scene::Material plastic;
    plastic.base_color = Rgb(0.1f);
    plastic.metallic = 0.0f;
    plastic.roughness = 0.05f;
    s.materials = {plastic, test::diffuse_material(Rgb(0.8f))};
    s.meshes.push_back(
        test::make_quad(Vec3(-20, 0, -10), Vec3(0, 0, 20), Vec3(40, 0, 0), kFloor));  // +Y
    s.meshes.push_back(
        test::make_quad(Vec3(-20, 0, -10), Vec3(40, 0, 0), Vec3(0, 20, 0), 1));  // +Z
    s.camera = test::look_at(Vec3(0.0f, 3.0f, 8.0f), Vec3(0.0f, 0.0f, -4.0f), 0.8f);
    s.has_camera = true;
    return s;
}

// Directional VPLs travelling along `dirs` (no shadows are cast in this scene but by the wall's
// and floor's own planes).
light::VplSet directional(const std::vector<Vec3>& dirs) {
    light::VplSet set;
    for (const Vec3& d : dirs) {
        light::Vpl v;
        v.type = light::VplType::Directional;
        v.normal = glm::normalize(d);
        v.power = Rgb(1.0f, 0.9f, 0.8f);
        set.vpls.push_back(v);
    }
    return set;
}

enum class Kind { Background, Unchained, Chained };

// What each floor pixel's centre sees (jitter off: the only sub-pixel position), as the chain
// layer decides it: whether the camera path continues at its first vertex.
std::vector<Kind> pixel_kinds(const scene::Scene& s, int res, const light::ChainOptions& options) {
    const trace::Accel accel(s);
    const light::LightSampler lights(s);
    std::vector<Kind> kinds(size_t(res) * size_t(res), Kind::Background);
    for (int y = 0; y < res; ++y) {
        for (int x = 0; x < res; ++x) {
            const scene::CameraRay cr = scene::generate_camera_ray(
                s.camera, res, res, Vec2(float(x) + 0.5f, float(y) + 0.5f));
            const trace::Ray ray{cr.origin, cr.direction};
            const std::optional<trace::Hit> hit = accel.intersect_camera(ray);
            if (!hit || trace::make_interaction(s, *hit, ray).material != kFloor) continue;
            Rng rng = light::chain_rng(0, uint64_t(y) * uint64_t(res) + uint64_t(x), 0);
            const bool chained =
                light::make_chained_receiver(s, accel, ray, rng, options, nullptr, &lights)
                    .continued;
            kinds[size_t(y) * size_t(res) + size_t(x)] = chained ? Kind::Chained : Kind::Unchained;
        }
    }
    return kinds;
}

struct Boundary {
    int dark_pixels = 0;       // pixels of the dark kind that are not exactly 0 (must be none)
    int dark_next_to_lit = 0;  // of those, the ones with a lit neighbour of the other kind
};

// The dark kind's pixels must be exactly 0: every VPL contributes 0 to their receivers, so any
// share of a neighbour of the other kind (whose own value is > 0) would show.
Boundary check_boundary(const Image& image, const std::vector<Kind>& kinds, int res, Kind dark) {
    const Kind lit = dark == Kind::Chained ? Kind::Unchained : Kind::Chained;
    Boundary b;
    for (int y = 0; y < res; ++y) {
        for (int x = 0; x < res; ++x) {
            if (kinds[size_t(y) * size_t(res) + size_t(x)] != dark) continue;
            const Rgb v = image.at(x, y);
            if (v.r != 0.0f || v.g != 0.0f || v.b != 0.0f) ++b.dark_pixels;
            bool next_to_lit = false;
            // K = 2's window: the 3 × 3 pixels around (away from the border).
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) {
                    const int qx = x + dx;
                    const int qy = y + dy;
                    if (qx < 1 || qy < 1 || qx >= res - 1 || qy >= res - 1) continue;
                    if (kinds[size_t(qy) * size_t(res) + size_t(qx)] == lit &&
                        luminance(image.at(qx, qy)) > 0.0f)
                        next_to_lit = true;
                }
            }
            if (next_to_lit && x >= 1 && y >= 1 && x < res - 1 && y < res - 1) ++b.dark_next_to_lit;
        }
    }
    return b;
}

// Light parallel to the floor (it lights the wall, not the floor): the unchained floor pixels
// must stay exactly 0 beside lit chained ones. Light from above, parallel to the wall: the
// chained pixels (whose chains end on the wall or leave the scene) must stay 0 beside the lit
// unchained floor. Both on the GPU and in the oracle; a filter that mixed the two kinds — the
// G-buffer's test alone accepts them — would move each boundary pixel by a share of its lit
// neighbours', a quarter or more of their value.
TEST_F(InterleaveChainsTest, TheFilterNeverMixesChainedAndUnchainedPixels) {
    const scene::Scene s = floor_and_wall();
    constexpr int kRes = 40;
    test::VplRenderSettings settings{.res = kRes, .shadow_res = 64, .clamp = 0.0f};
    settings.jitter = false;
    settings.chain_roughness = light::kDefaultChainRoughness;
    settings.interleave = 2;
    light::ChainOptions options;
    options.max_roughness = settings.chain_roughness;
    const std::vector<Kind> kinds = pixel_kinds(s, kRes, options);
    int chained = 0, unchained = 0;
    for (const Kind k : kinds) {
        chained += k == Kind::Chained;
        unchained += k == Kind::Unchained;
    }
    ASSERT_GT(chained, kRes);
    ASSERT_GT(unchained, kRes);

    struct Case {
        const char* name;
        light::VplSet vpls;
        Kind dark;
    };
    // Four VPLs at least, so that every pixel class of K = 2 shades one.
    const std::vector<Case> cases = {
        {"light along the floor",
         directional(
             {{0.0f, 0.0f, -1.0f}, {0.3f, 0.0f, -1.0f}, {-0.3f, 0.0f, -1.0f}, {0.1f, 0.0f, -1.0f}}),
         Kind::Unchained},
        {"light from above",
         directional(
             {{0.0f, -1.0f, 0.0f}, {0.3f, -1.0f, 0.0f}, {-0.3f, -1.0f, 0.0f}, {0.1f, -1.0f, 0.0f}}),
         Kind::Chained},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        const Image gpu = test::gpu_render(context(), s, c.vpls, settings);
        const Image oracle = test::oracle_render(s, c.vpls, settings);
        for (const auto& [what, image] : {std::pair{"gpu", &gpu}, std::pair{"oracle", &oracle}}) {
            SCOPED_TRACE(what);
            const Boundary b = check_boundary(*image, kinds, kRes, c.dark);
            EXPECT_EQ(b.dark_pixels, 0);
            // A whole row of boundary pixels at least, so the case can fail.
            EXPECT_GT(b.dark_next_to_lit, kRes / 2);
            std::printf("%s, %s: %d dark pixels beside lit ones\n", c.name, what,
                        b.dark_next_to_lit);
        }
    }
}

}  // namespace
}  // namespace mvpl::render
