// The progressive interface of VplRenderer (begin / accumulate / resolve), which time budgets and
// the preview use, against the one-shot render() of the same VPLs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <span>
#include <string>

#include "engine/core/finite_check.h"
#include "engine/gpu/gpu_error.h"
#include "engine/gpu/memory.h"
#include "engine/light/light_sampler.h"
#include "engine/render/vpl_renderer.h"
#include "engine/sampler/monte_carlo_sampler.h"
#include "engine/scene/scene_loader.h"
#include "engine/trace/accel.h"
#include "tests/gpu/gpu_test.h"
#include "tests/support/scaled_vpls.h"

namespace mvpl::render {
namespace {

using ProgressiveRenderTest = gpu::testing::GpuTest;

constexpr uint64_t kPaths = 48;

struct CornellBox {
    scene::Scene scene = scene::load_scene(MVPL_ASSETS_DIR "/cornell-box/cbox.gltf");
    light::VplSet set;             // powers as traced, scale 1/kPaths
    std::vector<light::Vpl> vpls;  // the same with the scale folded into the powers

    CornellBox() {
        const trace::Accel accel(scene);
        const light::LightSampler lights(scene);
        sampler::MonteCarloOptions o;
        o.paths = kPaths;
        o.seed = 3;
        set = sampler::MonteCarloSampler(scene, accel, lights).generate(o);
        vpls = test::with_scale_applied(set);
    }
};

RenderOptions small_options() {
    RenderOptions o;
    o.width = o.height = 48;
    o.shadow_resolution = 64;
    o.batch = 8;
    o.clamp = 0.05f;
    return o;
}

// Accumulates `vpls` in calls of the given sizes (the last takes what is left).
void accumulate_in_chunks(VplRenderer& renderer, std::span<const light::Vpl> vpls,
                          std::initializer_list<size_t> chunks) {
    size_t first = 0;
    for (const size_t chunk : chunks) {
        const size_t count = std::min(chunk, vpls.size() - first);
        renderer.accumulate(vpls.subspan(first, count));
        first += count;
    }
    ASSERT_EQ(first, vpls.size());
}

// Both images sum the same float contributions, in other chunks or with the scale folded into
// the powers instead of applied at the resolve: each pixel differs by float rounding only — a few
// ulps of the sum of at most ~200 terms, far below 1e-5 relative (plus an absolute 1e-7 for
// pixels that are ~0).
void expect_same_image(const Image& a, const Image& b) {
    ASSERT_EQ(a.width(), b.width());
    ASSERT_EQ(a.height(), b.height());
    int differing = 0;
    for (size_t i = 0; i < a.pixels().size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            const float x = a.pixels()[i][c], y = b.pixels()[i][c];
            if (!(std::abs(x - y) <= 1e-5f * std::max(std::abs(x), std::abs(y)) + 1e-7f))
                ++differing;
        }
    }
    EXPECT_EQ(differing, 0);
}

TEST_F(ProgressiveRenderTest, UnevenChunksWithAScaleEqualTheOneShotRender) {
    const CornellBox box;
    ASSERT_GT(box.vpls.size(), 20u);
    VplRenderer renderer(context(), box.scene);
    const Image one_shot = renderer.render(box.set, small_options());

    const std::vector<light::Vpl>& unscaled = box.set.vpls;
    renderer.begin(box.scene.camera, small_options());
    // Chunks that straddle batches: 1, 7, 13, then the rest.
    accumulate_in_chunks(renderer, unscaled, {1, 7, 13, unscaled.size()});
    EXPECT_EQ(renderer.timings().batches, 1u + 1u + 2u + (unscaled.size() - 21 + 7) / 8);
    expect_same_image(renderer.resolve(1.0 / double(kPaths)), one_shot);
}

// Sub-pixel positions follow the VPL index since begin(), not the calls: with a G-buffer every
// two batches (16 VPLs a position) uneven chunks still give the one-shot image, one G-buffer per
// position; without jitter there is one G-buffer whatever the count.
TEST_F(ProgressiveRenderTest, GBuffersFollowThePositionsNotTheChunks) {
    const CornellBox box;
    VplRenderer renderer(context(), box.scene);
    RenderOptions o = small_options();
    o.batches_per_position = 2;
    RenderTimings timings;
    const Image one_shot = renderer.render(box.set, o, &timings);
    const uint32_t positions = uint32_t((box.set.vpls.size() + 15) / 16);
    EXPECT_EQ(timings.g_buffers, positions);
    renderer.begin(box.scene.camera, o);
    accumulate_in_chunks(renderer, box.set.vpls, {5, 11, 17, box.set.vpls.size()});
    EXPECT_EQ(renderer.timings().g_buffers, positions);
    expect_same_image(renderer.resolve(1.0 / double(kPaths)), one_shot);
    o.jitter = false;
    renderer.render(box.set, o, &timings);
    EXPECT_EQ(timings.g_buffers, 1u);
}

// On two devices (VplRenderer's `devices`) each call's batches are cut into two runs and the
// image is the devices' sum: the one-device image, in uneven chunks, interleaved (a position's
// batches filtered on each device), with each position's emission added once. A device whose
// image were left out, whose VPLs were shaded at another position or pixel class, or a position
// whose emission were added twice (it is drawn by both devices where a run starts), would differ.
TEST_F(ProgressiveRenderTest, TwoDevicesSumToTheOneDeviceImage) {
    const CornellBox box;
    RenderOptions o = small_options();
    o.interleave = 2;
    o.batches_per_position = 2;
    VplRenderer one(context(), box.scene);
    const Image expected = one.render(box.set, o);
    VplRenderer two(context(), box.scene, nullptr, 2);
    EXPECT_EQ(two.devices(), 2u);
    RenderTimings timings;
    expect_same_image(two.render(box.set, o, &timings), expected);
    const uint32_t positions = uint32_t((box.set.vpls.size() + 15) / 16);
    ASSERT_GE(positions, 3u);
    // One call: device 1's run starts at batch ⌈B/2⌉ (render::split_into_runs); inside a
    // position (an odd batch, two a position) device 0 drew that position too.
    const uint32_t batches = uint32_t((box.set.vpls.size() + 7) / 8);
    EXPECT_EQ(timings.g_buffers, positions + ((batches + 1) / 2) % 2);
    EXPECT_EQ(timings.batches, uint32_t((box.set.vpls.size() + 7) / 8));
    two.begin(box.scene.camera, o);
    accumulate_in_chunks(two, box.set.vpls, {5, 11, 17, box.set.vpls.size()});
    EXPECT_GE(two.timings().g_buffers, positions);
    expect_same_image(two.resolve(box.set.scale), expected);
    // Device 1's memory counts too (device 0's context is the suite's, which `one` shares).
    EXPECT_GT(two.peak_device_bytes(), context().allocator().peak_bytes());
    EXPECT_THROW(VplRenderer(context(), box.scene, nullptr, 0), gpu::GpuError);
}

// Ranks over devices: two "ranks" take alternate runs of batches, given by index as a cluster's
// shares are, each on two devices; their contributions summed and resolved by the first give the
// one-device image, with jitter and without: each position's emission once, the positions whose
// first VPL the first rank never shaded drawn by its resolve.
TEST_F(ProgressiveRenderTest, RanksOnTwoDevicesSumToTheOneDeviceImage) {
    const CornellBox box;
    VplRenderer one(context(), box.scene);
    VplRenderer first(context(), box.scene, nullptr, 2), second(context(), box.scene, nullptr, 2);
    for (const bool jitter : {true, false}) {
        SCOPED_TRACE(jitter);
        RenderOptions o = small_options();
        o.jitter = jitter;
        o.batches_per_position = 2;
        const Image expected = one.render(box.set, o);
        std::vector<light::Vpl> vpls[2];
        std::vector<uint64_t> index[2];
        // Runs of three batches, positions of two: each rank starts some positions.
        for (size_t i = 0; i < box.set.vpls.size(); ++i) {
            vpls[(i / (3 * o.batch)) % 2].push_back(box.set.vpls[i]);
            index[(i / (3 * o.batch)) % 2].push_back(i);
        }
        ASSERT_GT(box.set.vpls.size(), 5u * o.batch);
        first.begin(box.scene.camera, o);
        second.begin(box.scene.camera, o);
        first.accumulate(vpls[0], index[0]);
        second.accumulate(vpls[1], index[1]);
        Image sum = first.contributions();
        const Image more = second.contributions();
        for (size_t i = 0; i < sum.pixels().size(); ++i)
            sum.pixels()[i] += more.pixels()[i];
        expect_same_image(first.resolve(box.set.scale, sum, box.set.vpls.size()), expected);
    }
}

// Interleaved, the shares of a position's batches add up in one image that is filtered once per
// position (and at the end of each call): two batches of 8 per position give the image of one
// batch of 16 per position (the same positions, and a VPL's pixel class is its index mod K²),
// however the calls cut them. Overwriting the shares, or filtering only at a position's change,
// would lose a batch.
TEST_F(ProgressiveRenderTest, InterleavedBatchesOfAPositionFilterAsOne) {
    const CornellBox box;
    VplRenderer renderer(context(), box.scene);
    RenderOptions two = small_options();
    two.interleave = 2;
    two.batches_per_position = 2;
    RenderOptions one = two;
    one.batch = 16;
    one.batches_per_position = 1;
    const Image per_position = renderer.render(box.set, one);
    RenderTimings timings;
    expect_same_image(renderer.render(box.set, two, &timings), per_position);
    EXPECT_EQ(timings.batches, uint32_t((box.set.vpls.size() + 7) / 8));
    renderer.begin(box.scene.camera, two);
    accumulate_in_chunks(renderer, box.set.vpls, {3, 9, 6, box.set.vpls.size()});
    expect_same_image(renderer.resolve(box.set.scale), per_position);
}

TEST_F(ProgressiveRenderTest, ScaleMultipliesTheVplsButNotTheEmission) {
    const CornellBox box;
    VplRenderer renderer(context(), box.scene);
    renderer.begin(box.scene.camera, small_options());
    renderer.accumulate(box.vpls);
    const Image zero = renderer.resolve(0.0);
    const Image one = renderer.resolve(1.0);
    const Image three = renderer.resolve(3.0);

    // Scale 0: the luminaire seen directly and nothing else.
    int emitting = 0, lit = 0;
    for (size_t i = 0; i < zero.pixels().size(); ++i) {
        const float e = max_component(zero.pixels()[i]);
        if (e > 0.0f) ++emitting;
        if (max_component(one.pixels()[i]) > 0.0f) ++lit;
        for (int c = 0; c < 3; ++c) {
            const double expected = 3.0 * one.pixels()[i][c] - 2.0 * zero.pixels()[i][c];
            EXPECT_NEAR(three.pixels()[i][c], expected, 1e-5 * std::abs(expected) + 1e-6);
        }
    }
    EXPECT_GT(emitting, 0);                               // the luminaire is in view
    EXPECT_LT(emitting, int(zero.pixels().size()) / 10);  // and small
    EXPECT_GT(lit, int(zero.pixels().size()) / 2);
}

TEST_F(ProgressiveRenderTest, BeginClearsTheAccumulationAndTakesTheNewCamera) {
    const CornellBox box;
    VplRenderer renderer(context(), box.scene);
    const Image one_shot = renderer.render({box.vpls}, small_options());

    // The moved view must look like a renderer built for a scene with that camera.
    scene::Scene moved_scene = box.scene;
    const float step = 0.1f * box.scene.bounds().diagonal();
    moved_scene.camera.camera_to_world[3] += Vec4(step, 0.5f * step, 0.0f, 0.0f);
    const Image moved_one_shot =
        VplRenderer(context(), moved_scene).render({box.vpls}, small_options());
    renderer.begin(moved_scene.camera, small_options());
    renderer.accumulate(box.vpls);
    const Image other_view = renderer.resolve(1.0);
    expect_same_image(other_view, moved_one_shot);
    double difference = 0.0, total = 0.0;
    for (size_t i = 0; i < one_shot.pixels().size(); ++i) {
        difference += std::abs(luminance(one_shot.pixels()[i]) - luminance(other_view.pixels()[i]));
        total += luminance(one_shot.pixels()[i]);
    }
    EXPECT_GT(difference, 0.02 * total);  // the view did move

    renderer.begin(box.scene.camera, small_options());
    renderer.accumulate(box.vpls);
    expect_same_image(renderer.resolve(1.0), one_shot);
}

// The NaN/Inf guard: one VPL with a non-finite power poisons every pixel it lights, and the
// resolve refuses to return the image instead of writing it.
TEST_F(ProgressiveRenderTest, NonFinitePixelsFailTheResolveLoudly) {
    const CornellBox box;
    VplRenderer renderer(context(), box.scene);
    for (const float bad :
         {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
        std::vector<light::Vpl> vpls = box.vpls;
        vpls[vpls.size() / 2].power = Rgb(bad, 1.0f, 1.0f);
        renderer.begin(box.scene.camera, small_options());
        renderer.accumulate(vpls);
        try {
            renderer.resolve(1.0);
            ADD_FAILURE() << "a non-finite image was returned";
        } catch (const NonFiniteError& e) {
            EXPECT_NE(std::string(e.what()).find("non-finite pixel"), std::string::npos)
                << e.what();
            EXPECT_NE(std::string(e.what()).find("the first at ("), std::string::npos) << e.what();
        }
    }
    // The same renderer still resolves a clean image afterwards.
    renderer.begin(box.scene.camera, small_options());
    renderer.accumulate(box.vpls);
    EXPECT_NO_THROW(renderer.resolve(1.0));
}

// The passes of the sizes used before are parked and taken again (the preview's motion and full
// resolutions), interleaved so that the interleave filter is parked too: back at a size, the
// image is the one a new renderer makes, also after a batch change in between (which must not
// bring back passes built for the old batch).
TEST_F(ProgressiveRenderTest, PassesParkedForEarlierSizesGiveAFreshRenderersImage) {
    const CornellBox box;
    RenderOptions full = small_options(), half = small_options();
    full.interleave = half.interleave = 2;
    half.width = half.height = full.width / 2;
    VplRenderer fresh(context(), box.scene);
    const Image expected = fresh.render(box.set, full);
    VplRenderer renderer(context(), box.scene);
    for (const RenderOptions& o : {full, half, full, half})
        renderer.render(box.set, o);
    expect_same_image(renderer.render(box.set, full), expected);
    RenderOptions other_batch = half;
    other_batch.batch = 4;
    renderer.render(box.set, other_batch);
    full.batch = 4;
    VplRenderer fresh_batch(context(), box.scene);
    expect_same_image(renderer.render(box.set, full), fresh_batch.render(box.set, full));
}

TEST_F(ProgressiveRenderTest, AccumulateBeforeBeginIsAnError) {
    const CornellBox box;
    VplRenderer renderer(context(), box.scene);
    EXPECT_THROW(renderer.accumulate(box.vpls), gpu::GpuError);
    EXPECT_THROW(renderer.resolve(1.0), gpu::GpuError);
}

}  // namespace
}  // namespace mvpl::render
