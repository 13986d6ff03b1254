// The reference traced in chunks (engine/reference/progressive_trace.h, path_film.h): for the
// same samples per pixel, the image of one pass to the bit, against an independent per-pixel loop
// written here as the path tracer sums (one generator a pixel seeded
// (mix_bits(seed), pixel), the samples in order, summed in double); a gate that says no ends it
// between chunks with the samples so far; chunk sizes from the clock.
#include <gtest/gtest.h>

#include <atomic>
#include <vector>

#include "engine/light/light_sampler.h"
#include "engine/reference/path_film.h"
#include "engine/reference/path_tracer.h"
#include "engine/reference/progressive_trace.h"
#include "engine/scene/camera.h"
#include "engine/trace/accel.h"
#include "tests/support/scene_builder.h"

namespace mvpl {
namespace {

struct Fixture {
    scene::Scene scene = test::make_integrating_sphere(0.6f, 1.0f, 4.0f);
    trace::Accel accel{scene};
    light::LightSampler lights{scene};
    reference::PathTracer tracer{scene, accel, lights};
    reference::PathTracerOptions options;
    Fixture() {
        options.width = 12;
        options.height = 10;
        options.spp = 7;
        options.max_depth = -1;  // Russian roulette: paths of every length, numbers drawn unevenly
        options.seed = 5;
        options.quiet = true;
    }
};

// The image as one loop over each pixel's samples, independent of PathFilm.
Image one_pass(const Fixture& f, int spp) {
    const reference::PathTracerOptions& o = f.options;
    Image image(o.width, o.height);
    for (int y = 0; y < o.height; ++y) {
        for (int x = 0; x < o.width; ++x) {
            Rng rng(mix_bits(o.seed), uint64_t(y) * uint64_t(o.width) + uint64_t(x));
            DVec3 sum(0.0);
            for (int s = 0; s < spp; ++s) {
                const float u = rng.next_float();
                const Vec2 film(float(x) + u, float(y) + rng.next_float());
                const scene::CameraRay cr =
                    scene::generate_camera_ray(f.scene.camera, o.width, o.height, film);
                const Rgb L =
                    f.tracer.radiance({cr.origin, cr.direction}, rng, o.max_depth, o.rr_depth);
                if (is_finite(L)) sum += DVec3(L);
            }
            image.at(x, y) = Rgb(sum / double(spp));
        }
    }
    return image;
}

void expect_same_pixels(const Image& a, const Image& b) {
    ASSERT_EQ(a.pixels().size(), b.pixels().size());
    for (size_t i = 0; i < a.pixels().size(); ++i)
        ASSERT_EQ(a.pixels()[i], b.pixels()[i]) << "pixel " << i;
}

TEST(ProgressiveTrace, ChunksGiveTheImageOfOnePass) {
    const Fixture f;
    const Image expected = one_pass(f, f.options.spp);
    EXPECT_GT(expected.mean().g, 0.0f);
    expect_same_pixels(f.tracer.render(f.options), expected);
    // 1 + 2 + 4 samples; the hook sees every pixel's sample indices 0..6 once each.
    reference::PathFilm film(f.options.width, f.options.height, f.options.seed);
    std::vector<std::atomic<int>> seen(size_t(f.options.width) * f.options.height);
    const reference::CameraSampleHook hook = [&](int x, int y, int sample, const Vec2&) {
        seen[size_t(y) * f.options.width + x].fetch_or(1 << sample);
    };
    reference::RenderStats stats;
    for (const int chunk : {1, 2, 4})
        f.tracer.advance(film, chunk, f.options, &stats, hook);
    EXPECT_EQ(film.spp(), 7);
    EXPECT_EQ(stats.paths, uint64_t(12 * 10 * 7));
    expect_same_pixels(film.image(), expected);
    for (const std::atomic<int>& bits : seen)
        EXPECT_EQ(bits.load(), 0x7f);
}

TEST(ProgressiveTrace, AGateThatSaysNoKeepsTheSamplesSoFar) {
    const Fixture f;
    reference::PathFilm film(f.options.width, f.options.height, f.options.seed);
    std::vector<int> asked;
    reference::trace_progressively(f.tracer, film, f.options, nullptr, {},
                                   [&](const reference::PathFilm& so_far) {
                                       asked.push_back(so_far.spp());
                                       return so_far.spp() == 0;  // the first chunk alone
                                   });
    EXPECT_EQ(asked, (std::vector<int>{0, 1}));  // the first chunk is one sample
    EXPECT_EQ(film.spp(), 1);
    expect_same_pixels(film.image(), one_pass(f, 1));
    // A gate that always agrees reaches --spp, and the image of one pass.
    reference::PathFilm whole(f.options.width, f.options.height, f.options.seed);
    reference::trace_progressively(f.tracer, whole, f.options, nullptr, {},
                                   [](const reference::PathFilm&) { return true; });
    EXPECT_EQ(whole.spp(), f.options.spp);
    expect_same_pixels(whole.image(), one_pass(f, f.options.spp));
    // Nothing traced: black, not 0/0.
    const reference::PathFilm empty(2, 2, 0);
    EXPECT_EQ(empty.image().at(1, 1), Rgb(0.0f));
}

TEST(ProgressiveTrace, ChunksAreSizedByTheClock) {
    using reference::kChunkSeconds;
    using reference::next_spp_chunk;
    EXPECT_EQ(next_spp_chunk(0, 0.0, 100), 1);                    // nothing measured yet
    EXPECT_EQ(next_spp_chunk(4, kChunkSeconds / 8.0, 1000), 32);  // 8 chunks' worth a sample
    EXPECT_EQ(next_spp_chunk(4, kChunkSeconds / 8.0, 10), 10);    // never past --spp
    EXPECT_EQ(next_spp_chunk(1, 10.0 * kChunkSeconds, 10), 1);    // at least one
    EXPECT_EQ(next_spp_chunk(5, 1.0, 0), 0);                      // done
}

}  // namespace
}  // namespace mvpl
