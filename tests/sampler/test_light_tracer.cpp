// The light tracer and the Monte Carlo sampler: determinism, thread-count independence, the depth
// rule (a VPL of path_length k serves camera paths of k + 2 segments), and the emitter VPLs.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cstring>

#include "engine/light/light_sampler.h"
#include "engine/sampler/monte_carlo_sampler.h"
#include "engine/sampler/sample_stream.h"
#include "engine/scene/scene_loader.h"
#include "engine/trace/accel.h"
#include "tests/sampler/vpl_test_util.h"
#include "tests/support/scaled_vpls.h"
#include "tests/support/scene_builder.h"

namespace mvpl {
namespace {

using sampler::MonteCarloOptions;

bool same_vpls(const std::vector<light::Vpl>& a, const std::vector<light::Vpl>& b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i) {
        const light::Vpl &x = a[i], &y = b[i];
        if (x.type != y.type || x.position != y.position || x.normal != y.normal ||
            x.shading_normal != y.shading_normal || x.wi != y.wi || x.power != y.power ||
            x.path_length != y.path_length)
            return false;
    }
    return true;
}

class CornellSampler : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        s_scene = new scene::Scene(scene::load_scene(MVPL_ASSETS_DIR "/cornell-box/cbox.gltf"));
        s_accel = new trace::Accel(*s_scene);
        s_lights = new light::LightSampler(*s_scene);
    }
    static void TearDownTestSuite() {
        delete s_lights;
        delete s_accel;
        delete s_scene;
    }
    std::vector<light::Vpl> generate(const MonteCarloOptions& o) const {
        return test::with_scale_applied(
            sampler::MonteCarloSampler(*s_scene, *s_accel, *s_lights).generate(o));
    }
    static scene::Scene* s_scene;
    static trace::Accel* s_accel;
    static light::LightSampler* s_lights;
};
scene::Scene* CornellSampler::s_scene = nullptr;
trace::Accel* CornellSampler::s_accel = nullptr;
light::LightSampler* CornellSampler::s_lights = nullptr;

TEST_F(CornellSampler, DeterministicForASeed) {
    for (bool qmc : {false, true}) {
        MonteCarloOptions o;
        o.paths = 700;
        o.qmc = qmc;
        o.seed = 3;
        const auto a = generate(o), b = generate(o);
        EXPECT_TRUE(same_vpls(a, b)) << "qmc " << qmc;
        EXPECT_GT(a.size(), o.paths);  // emitter VPLs plus bounces
        o.seed = 4;
        EXPECT_FALSE(same_vpls(a, generate(o))) << "qmc " << qmc;
    }
}

TEST_F(CornellSampler, IndependentOfThreadCount) {
    for (auto per_path : {sampler::VplsPerPath::All, sampler::VplsPerPath::One}) {
        MonteCarloOptions o;
        o.paths = 1500;  // several blocks
        o.seed = 9;
        o.per_path = per_path;
        std::vector<light::Vpl> one, many;
        {
            tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
            one = generate(o);
        }
        {
            tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 4);
            many = generate(o);
        }
        EXPECT_TRUE(same_vpls(one, many));
        if (per_path == sampler::VplsPerPath::One) {
            EXPECT_LE(one.size(), o.paths);
        }
    }
}

TEST_F(CornellSampler, PathLengthsFollowMaxDepth) {
    MonteCarloOptions o;
    o.paths = 500;
    o.tracer.max_depth = 1;  // emitters seen directly only: no VPL at all
    EXPECT_TRUE(generate(o).empty());

    o.tracer.max_depth = 2;  // direct light: emitter VPLs only, one per path
    const auto direct = generate(o);
    EXPECT_EQ(direct.size(), o.paths);
    for (const auto& v : direct) {
        EXPECT_EQ(v.path_length, 0u);
        EXPECT_EQ(v.type, light::VplType::Area);
    }

    for (int depth : {3, 6}) {
        o.tracer.max_depth = depth;
        uint32_t longest = 0;
        for (const auto& v : generate(o)) {
            EXPECT_LE(int(v.path_length), depth - 2);
            EXPECT_EQ(v.type == light::VplType::Area, v.path_length == 0);
            longest = std::max(longest, v.path_length);
        }
        EXPECT_EQ(int(longest), depth - 2);
    }

    o.tracer.max_depth = -1;  // unlimited: Russian roulette ends the paths, some go far
    uint32_t longest = 0;
    for (const auto& v : generate(o))
        longest = std::max(longest, v.path_length);
    EXPECT_GT(longest, 4u);
}

TEST_F(CornellSampler, SurfaceVplsAreLitFromTheirSide) {
    MonteCarloOptions o;
    o.paths = 300;
    for (const auto& v : generate(o)) {
        EXPECT_TRUE(is_finite(v.power));
        EXPECT_GE(std::min(v.power.r, std::min(v.power.g, v.power.b)), 0.0f);
        if (v.type != light::VplType::Surface) continue;
        EXPECT_GT(glm::dot(v.wi, v.normal), 0.0f);
        EXPECT_GT(glm::dot(v.shading_normal, v.normal), 0.0f);
        EXPECT_NEAR(glm::length(v.wi), 1.0f, 1e-4f);
    }
}

// Emitter VPL powers: point I/(pick·N), area Le·area/(pick·N), directional E/(pick·N).
TEST(EmitterVpls, PowersFollowTheDensities) {
    scene::Scene s = test::area_lit_plane();
    scene::Light point;
    point.type = scene::LightType::Point;
    point.position = Vec3(0.5f, 1.0f, 0.0f);
    point.intensity = Rgb(2.0f);
    s.lights.push_back(point);
    const trace::Accel accel(s);
    const light::LightSampler lights(s);
    MonteCarloOptions o;
    o.paths = 400;
    o.tracer.max_depth = 2;
    const auto vpls =
        test::with_scale_applied(sampler::MonteCarloSampler(s, accel, lights).generate(o));
    ASSERT_EQ(vpls.size(), o.paths);
    const float n = float(o.paths);
    const float pick_point = lights.emitters().back().power / lights.total_power();
    const float quad_area = 0.8f * 0.8f;
    for (const auto& v : vpls) {
        if (v.type == light::VplType::Point) {
            EXPECT_NEAR(v.power.g, 2.0f / (pick_point * n), 1e-5f);
        } else {
            ASSERT_EQ(v.type, light::VplType::Area);
            EXPECT_NEAR(v.normal.y, -1.0f, 1e-6f);
            // Le·(1/pdf_area)/N with pdf_area = pick_quad / area: the two triangles of the quad
            // have the same power, so pick_triangle = (1 − pick_point)/2 and area = quad/2.
            const float expected = 3.0f * quad_area / ((1.0f - pick_point) * n);
            EXPECT_NEAR(v.power.g / expected, 1.0f, 1e-4f);
        }
    }
}

TEST(Halton, RadicalInverse) {
    EXPECT_DOUBLE_EQ(sampler::radical_inverse(1, 2), 0.5);
    EXPECT_DOUBLE_EQ(sampler::radical_inverse(3, 2), 0.75);
    EXPECT_DOUBLE_EQ(sampler::radical_inverse(6, 2), 0.375);
    EXPECT_NEAR(sampler::radical_inverse(1, 3), 1.0 / 3.0, 1e-15);
    EXPECT_NEAR(sampler::radical_inverse(5, 3), 2.0 / 3.0 + 1.0 / 9.0, 1e-15);
    const std::vector<float> shifts = sampler::halton_shifts(1, 3);
    for (uint64_t i = 0; i < 64; ++i) {
        sampler::HaltonStream u(i, shifts, 1, i);
        for (int d = 0; d < 6; ++d) {
            const float v = u.next();
            EXPECT_GE(v, 0.0f);
            EXPECT_LT(v, 1.0f);
        }
    }
}

}  // namespace
}  // namespace mvpl
