// The Metropolis VPL sampler and the sampler factory: determinism, β = 1 against Monte Carlo, the
// direction of the two-room scene, and a scene whose light reaches nothing the camera sees.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "engine/core/error.h"
#include "engine/light/light_sampler.h"
#include "engine/sampler/metropolis_stream.h"
#include "engine/sampler/monte_carlo_stream.h"
#include "engine/sampler/sampler_factory.h"
#include "engine/scene/scene_loader.h"
#include "engine/trace/accel.h"
#include "tests/support/scaled_vpls.h"
#include "tests/support/scene_builder.h"

namespace mvpl {
namespace {

using sampler::MetropolisOptions;
using sampler::MetropolisStream;

struct Loaded {
    explicit Loaded(scene::Scene s) : scene(std::move(s)), accel(scene), lights(scene) {}
    scene::Scene scene;
    trace::Accel accel;
    light::LightSampler lights;
};

MetropolisOptions small_options(uint64_t seed) {
    MetropolisOptions o;
    o.seed = seed;
    o.chains = 8;
    o.bootstrap = 512;
    o.importance.points = 64;
    o.importance.width = o.importance.height = 64;
    return o;
}

TEST(SamplerFactory, UnknownNameListsTheAvailableOnes) {
    const Loaded l(scene::load_scene(MVPL_ASSETS_DIR "/cornell-box/cbox.gltf"));
    try {
        sampler::make_vpl_stream("bogus", l.scene, l.accel, l.lights, l.scene.camera, {});
        FAIL() << "no exception";
    } catch (const UsageError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("bogus"), std::string::npos);
        EXPECT_NE(what.find("mc"), std::string::npos);
        EXPECT_NE(what.find("metropolis"), std::string::npos);
    }
}

// The progressive Monte Carlo stream traces the same paths as MonteCarloSampler::generate, its
// powers only scaled at the end (float rounding apart).
TEST(MonteCarloStream, MatchesGenerate) {
    const Loaded l(scene::load_scene(MVPL_ASSETS_DIR "/cornell-box/cbox.gltf"));
    sampler::MonteCarloOptions o;
    o.paths = 700;
    o.seed = 3;
    const auto whole = test::with_scale_applied(
        sampler::MonteCarloSampler(l.scene, l.accel, l.lights).generate(o));
    sampler::MonteCarloStream stream(l.scene, l.accel, l.lights, o);
    std::vector<light::Vpl> parts;
    stream.next(300, parts);
    stream.next(400, parts);
    ASSERT_EQ(stream.work_done(), 700u);
    ASSERT_EQ(whole.size(), parts.size());
    for (size_t i = 0; i < whole.size(); ++i) {
        EXPECT_EQ(whole[i].position, parts[i].position);
        const Rgb p = parts[i].power * float(stream.scale());
        EXPECT_NEAR(p.g, whole[i].power.g, 1e-5f * whole[i].power.g);
    }
}

TEST(MetropolisStream, DeterministicWhateverTheThreadCount) {
    const Loaded l(scene::load_scene(MVPL_ASSETS_DIR "/cornell-box/cbox.gltf"));
    auto run = [&](int threads) {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
        MetropolisStream m(l.scene, l.accel, l.lights, l.scene.camera, small_options(9));
        std::vector<light::Vpl> out;
        m.next(100, out);
        m.next(57, out);
        return out;
    };
    const auto a = run(1), b = run(4);
    ASSERT_EQ(a.size(), b.size());
    ASSERT_FALSE(a.empty());
    for (size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].position, b[i].position);
        EXPECT_EQ(a[i].power, b[i].power);
    }
}

// Σ scale·luminance(power) per path length: a linear functional of the VPL set whose expectation
// is the same for every unbiased sampler (Monte Carlo with all VPLs, Metropolis with one VPL per
// state weighted by b/I'). With β = 1 every proposal is an independent path, so the Metropolis
// estimate must match the Monte Carlo one in distribution's mean: over M independent runs each,
// the difference of means is within 5 standard errors (√(s²_mc/M + s²_m/M), the spreads measured;
// Student t with 2M − 2 ≈ 38 degrees of freedom, per length P(|t| > 5) ≈ 10⁻⁵).
TEST(MetropolisStream, LargeStepsOnlyMatchMonteCarlo) {
    const Loaded l(scene::load_scene(MVPL_ASSETS_DIR "/cornell-box/cbox.gltf"));
    constexpr int kRuns = 20, kLengths = 5;
    constexpr uint64_t kWork = 400;
    auto functional = [&](sampler::VplStream& s) {
        std::vector<light::Vpl> v;
        s.next(kWork, v);
        std::vector<double> sum(kLengths, 0.0);
        for (const light::Vpl& x : v)
            sum[std::min<size_t>(x.path_length, kLengths - 1)] +=
                s.scale() * double(luminance(x.power));
        return sum;
    };
    std::vector<std::vector<double>> mc(kLengths), metro(kLengths);
    for (int r = 0; r < kRuns; ++r) {
        sampler::MonteCarloOptions o;
        o.seed = 100 + uint64_t(r);
        sampler::MonteCarloStream s(l.scene, l.accel, l.lights, o);
        const auto f = functional(s);
        MetropolisOptions mo = small_options(200 + uint64_t(r));
        mo.large_step = 1.0f;
        MetropolisStream m(l.scene, l.accel, l.lights, l.scene.camera, mo);
        const auto g = functional(m);
        for (int k = 0; k < kLengths; ++k) {
            mc[k].push_back(f[k]);
            metro[k].push_back(g[k]);
        }
    }
    auto mean_var = [](const std::vector<double>& v) {
        double m = 0.0, s2 = 0.0;
        for (double x : v)
            m += x;
        m /= double(v.size());
        for (double x : v)
            s2 += (x - m) * (x - m);
        return std::pair<double, double>(m, s2 / double(v.size() - 1));
    };
    for (int k = 0; k < kLengths - 1; ++k) {
        const auto [m1, v1] = mean_var(mc[k]);
        const auto [m2, v2] = mean_var(metro[k]);
        ASSERT_GT(m1, 0.0) << "path length " << k;
        const double se = std::sqrt(v1 / kRuns + v2 / kRuns);
        EXPECT_NEAR(m2, m1, 5.0 * se) << "path length " << k;
    }
}

// Figure 4 of the seed: Monte Carlo leaves nearly all surface VPLs in the light's room (x < 0),
// while Metropolis, aiming at what the camera sees, puts many of them in the camera's room.
TEST(MetropolisStream, TwoRoomVplsGoWhereTheCameraLooks) {
    const Loaded l(scene::load_scene(MVPL_ASSETS_DIR "/two-room/two-room.gltf"));
    auto camera_room_share = [](const std::vector<light::Vpl>& v) {
        size_t surface = 0, camera_room = 0;
        for (const light::Vpl& x : v) {
            if (x.path_length == 0) continue;
            ++surface;
            camera_room += x.position.x > 0.0f ? 1 : 0;
        }
        return surface > 0 ? double(camera_room) / double(surface) : 0.0;
    };
    sampler::MonteCarloOptions o;
    sampler::MonteCarloStream mc(l.scene, l.accel, l.lights, o);
    std::vector<light::Vpl> a;
    mc.next(1000, a);
    MetropolisOptions mo;
    mo.seed = 1;
    mo.chains = 16;  // long enough chains (≈ 60 steps) that repeats occur and merge
    MetropolisStream m(l.scene, l.accel, l.lights, l.scene.camera, mo);
    std::vector<light::Vpl> b;
    m.next(1000, b);
    const double share_mc = camera_room_share(a), share_m = camera_room_share(b);
    // Measured: Monte Carlo 0.2%, Metropolis 40% at ε = 0.05 and 13% at the default ε = 1,
    // whose defensive half of the target goes where independent paths go (the rest mostly
    // room-A VPLs that light the camera's room or the wall seen through the hole, which the
    // target rightly wants). Bounds with room for other seeds: MC below 5%, Metropolis above 8%
    // and ten times MC's share.
    std::printf("camera-room share: mc %.3f, metropolis %.3f\n", share_mc, share_m);
    EXPECT_LT(share_mc, 0.05);
    EXPECT_GT(share_m, 0.08);
    EXPECT_GT(share_m, 10.0 * share_mc);
    EXPECT_GT(m.acceptance(), 0.0);
    EXPECT_LT(m.stats().emitted, m.stats().recorded);  // repeats were merged
}

// The light faces away from everything: no VPL lights a visible point. The stream says so,
// produces nothing and stays finite.
TEST(MetropolisStream, NoVisibleLightGivesNothingQuickly) {
    scene::Scene s;
    s.materials.push_back(test::diffuse_material(Rgb(0.6f)));
    scene::Material light = test::diffuse_material(Rgb(0.0f));
    light.emissive = Rgb(4.0f);
    s.materials.push_back(light);
    s.meshes.push_back(test::make_quad(Vec3(-2, 0, -2), Vec3(0, 0, 4), Vec3(4, 0, 0), 0));
    // cross(a, b) = (0,0,1)×(1,0,0) = (0,1,0): the light faces up, into empty space.
    s.meshes.push_back(
        test::make_quad(Vec3(-0.4f, 1.0f, -0.4f), Vec3(0, 0, 0.8f), Vec3(0.8f, 0, 0), 1));
    s.camera = test::look_at(Vec3(0.0f, 0.8f, 2.2f), Vec3(0.0f, 0.0f, 0.0f), 0.7f);
    s.has_camera = true;
    const Loaded l(std::move(s));
    MetropolisStream m(l.scene, l.accel, l.lights, l.scene.camera, small_options(0));
    EXPECT_TRUE(m.no_visible_light());
    std::vector<light::Vpl> out;
    m.next(1000, out);
    EXPECT_TRUE(out.empty());
    EXPECT_EQ(m.work_done(), 1000u);
    EXPECT_TRUE(std::isfinite(m.scale()));
    EXPECT_NE(m.statistics().find("no light"), std::string::npos);
}

}  // namespace
}  // namespace mvpl
