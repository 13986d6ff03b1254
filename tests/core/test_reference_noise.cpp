// The reference's own share of relMSE (engine/core/reference_noise.h): references made of a known
// image plus independent Gaussian noise of a known relative size.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "engine/core/error.h"
#include "engine/core/image.h"
#include "engine/core/image_metrics.h"
#include "engine/core/reference_noise.h"
#include "engine/core/rng.h"

namespace mvpl {
namespace {

constexpr int kSide = 128;

// A smooth image from dark (where relMSE's 10⁻² guard dominates) to bright.
Image truth() {
    Image t(kSide, kSide);
    for (int y = 0; y < kSide; ++y) {
        for (int x = 0; x < kSide; ++x)
            t.at(x, y) = Rgb(0.02f * float(x), 0.5f + 0.01f * float(y), 0.03f);
    }
    return t;
}

// t + noise whose standard deviation is `s` · sqrt(t² + 10⁻²) per pixel and channel, so that
// every pixel adds s² to the expected relMSE against t.
Image noisy(const Image& t, float s, uint64_t stream) {
    Rng rng(2026, stream);
    Image out = t;
    for (Rgb& p : out.pixels()) {
        for (int c = 0; c < 3; ++c) {
            // Box–Muller; 1 − u keeps the logarithm finite.
            const float u1 = 1.0f - rng.next_float(), u2 = rng.next_float();
            const float g = std::sqrt(-2.0f * std::log(u1)) * std::cos(6.2831853f * u2);
            p[c] += s * std::sqrt(p[c] * p[c] + 1e-2f) * g;
        }
    }
    return out;
}

TEST(ReferenceNoise, AverageIsThePixelMean) {
    Image a(2, 1), b(2, 1);
    a.at(0, 0) = Rgb(1.0f, 2.0f, 3.0f);
    b.at(0, 0) = Rgb(3.0f, 2.0f, 1.0f);
    b.at(1, 0) = Rgb(4.0f);
    const std::vector<Image> both{a, b};
    const Image m = average_images(both);
    EXPECT_EQ(m.at(0, 0), Rgb(2.0f));
    EXPECT_EQ(m.at(1, 0), Rgb(2.0f));
    EXPECT_EQ(reference_noise(std::vector<Image>{a}), 0.0);
    EXPECT_THROW(average_images(std::vector<Image>{a, Image(3, 1)}), UsageError);
    EXPECT_THROW(average_images(std::vector<Image>{}), UsageError);
}

// Three references with relative noise s: their mean carries s²/3, which is what no image can go
// below against it; subtracting it recovers the image's error against the truth. Tolerances: the
// estimates are means of n = 128² · 3 squared Gaussians, relative standard deviation √(2/n) =
// 0.64 % for the noise, and ≈ 0.75 % of the image's error for the difference (the noise term's
// 0.64 %/3 plus the cross term's 2/√(3n)); 4 % is over five of those. A share without the 1/M or
// the 1/2 would be off by 3× or 2×, and the uncorrected relMSE is 33 % above the truth's.
TEST(ReferenceNoise, RecoversTheErrorAgainstTheTruth) {
    const Image t = truth();
    const float s = 0.05f;  // 5 % per pixel: second-order terms ≈ s² ≈ 0.25 % of the estimates
    const std::vector<Image> refs{noisy(t, s, 1), noisy(t, s, 2), noisy(t, s, 3)};
    const double expected_noise = double(s) * s / 3.0;
    EXPECT_NEAR(reference_noise(refs), expected_noise, 0.04 * expected_noise);

    const Image x = noisy(t, s, 4);
    const double truth_error = compare_images(x, t).rel_mse;
    EXPECT_NEAR(truth_error, double(s) * s, 0.04 * double(s) * s);  // the construction itself
    const double against_refs = compare_images(x, average_images(refs)).rel_mse;
    EXPECT_GT(against_refs, 1.2 * truth_error);  // the references' noise shows
    EXPECT_NEAR(against_refs - reference_noise(refs), truth_error, 0.04 * truth_error);
}

}  // namespace
}  // namespace mvpl
