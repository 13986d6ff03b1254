// The Metropolis primary-sample state: wrapping, exact restore on reject, lazy = eager small
// steps in distribution, determinism per seed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/sampler/primary_sample_vector.h"

namespace mvpl {
namespace {

using sampler::PrimarySampleVector;

TEST(PrimarySampleVector, WrapStaysInUnitInterval) {
    EXPECT_EQ(sampler::wrap_unit(1.0), 0.0f);
    EXPECT_EQ(sampler::wrap_unit(-1e-12), 0.0f);  // rounds to 1.0f: that is 0 on the circle
    EXPECT_FLOAT_EQ(sampler::wrap_unit(-0.25), 0.75f);
    EXPECT_FLOAT_EQ(sampler::wrap_unit(2.5), 0.5f);
    // Wide small steps wrap often; every value read must stay in [0, 1).
    PrimarySampleVector u(7, 3, 0.7f);
    for (int i = 0; i < 2000; ++i) {
        u.start_iteration(i % 50 == 0);
        for (int d = 0; d < 8; ++d) {
            const float v = u.next();
            ASSERT_GE(v, 0.0f);
            ASSERT_LT(v, 1.0f);
        }
        if (i % 3 == 0) {
            u.reject();
        } else {
            u.accept();
        }
    }
}

TEST(PrimarySampleVector, RejectRestoresExactly) {
    PrimarySampleVector u(1, 2, 0.05f);
    for (int d = 0; d < 10; ++d)
        u.next();  // iteration 0: the first (large-step) state
    for (int step = 0; step < 200; ++step) {
        std::vector<float> before;
        const size_t dims = u.dimensions();
        for (size_t d = 0; d < dims; ++d)
            before.push_back(u.value(d));
        const bool large = step % 4 == 0;
        u.start_iteration(large);
        // Read more dimensions than before now and then: new ones must be restored too.
        const int read = 5 + step % 12;
        for (int d = 0; d < read; ++d)
            u.next();
        if (step % 2 == 0) {
            u.reject();
            for (size_t d = 0; d < dims; ++d)
                ASSERT_EQ(u.value(d), before[d]) << "step " << step << " dimension " << d;
        } else {
            u.accept();
        }
    }
}

// A dimension read at every small step (eager) and one read only after k small steps (lazy) must
// end at the same distribution around their start: wrapped N(0, kσ²). Two-sample Kolmogorov–
// Smirnov on M samples each: at significance 10⁻³ the critical distance is
// 1.95·√(2/M) (Smirnov's asymptotic c(α) = √(−ln(α/2)/2) = 1.95).
TEST(PrimarySampleVector, LazySmallStepsEqualEagerInDistribution) {
    constexpr int kSamples = 3000, kSteps = 16;
    constexpr float kSigma = 0.04f;
    auto wrapped_difference = [](float a, float b) {
        double d = double(a) - double(b);
        return d - std::floor(d + 0.5);  // in [−0.5, 0.5)
    };
    std::vector<double> eager, lazy;
    for (int s = 0; s < kSamples; ++s) {
        PrimarySampleVector e(11, uint64_t(s), kSigma);
        const float e0 = e.next();
        float e_last = e0;
        for (int k = 0; k < kSteps; ++k) {
            e.start_iteration(false);
            e_last = e.next();
            e.accept();
        }
        eager.push_back(wrapped_difference(e_last, e0));

        // Dimension 1 is read at iteration 0 and then not again until the kSteps-th small step:
        // its kSteps steps are applied lazily, in one normal step of variance kσ².
        PrimarySampleVector m(13, uint64_t(s), kSigma);
        m.next();
        const float m1_start = m.next();
        for (int k = 0; k < kSteps - 1; ++k) {
            m.start_iteration(false);
            m.next();  // dimension 0 only
            m.accept();
        }
        m.start_iteration(false);
        m.next();
        const float m1 = m.next();
        m.accept();
        lazy.push_back(wrapped_difference(m1, m1_start));
    }
    std::sort(eager.begin(), eager.end());
    std::sort(lazy.begin(), lazy.end());
    // KS distance between the two empirical distribution functions.
    double ks = 0.0;
    size_t i = 0, j = 0;
    while (i < eager.size() && j < lazy.size()) {
        if (eager[i] <= lazy[j]) {
            ++i;
        } else {
            ++j;
        }
        ks = std::max(ks, std::abs(double(i) / kSamples - double(j) / kSamples));
    }
    EXPECT_LT(ks, 1.95 * std::sqrt(2.0 / kSamples));
    // And both have the wrapped normal's spread, σ√k = 0.16 (wrapping at ±0.5 is 3σ away, so the
    // standard deviation is within 2% of it); the standard error of a sample standard deviation
    // is σ/√(2M) ≈ 1.3% of it, 4 of those plus the 2% margin bound the check.
    for (const auto* v : {&eager, &lazy}) {
        double sum2 = 0.0;
        for (double x : *v)
            sum2 += x * x;
        const double sd = std::sqrt(sum2 / double(v->size()));
        EXPECT_NEAR(sd, kSigma * std::sqrt(double(kSteps)), 0.075 * kSigma * std::sqrt(kSteps));
    }
}

TEST(PrimarySampleVector, DeterministicPerSeed) {
    auto run = [](uint64_t seed, uint64_t stream) {
        PrimarySampleVector u(seed, stream, 0.02f);
        std::vector<float> out;
        for (int i = 0; i < 300; ++i) {
            u.start_iteration(i % 7 == 0);
            for (int d = 0; d < 3 + i % 9; ++d)
                out.push_back(u.next());
            if (i % 3 == 0) {
                u.reject();
            } else {
                u.accept();
            }
        }
        return out;
    };
    EXPECT_EQ(run(5, 9), run(5, 9));
    EXPECT_NE(run(5, 9), run(5, 10));
    EXPECT_NE(run(5, 9), run(6, 9));
}

}  // namespace
}  // namespace mvpl
