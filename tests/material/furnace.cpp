#include "tests/material/furnace.h"

#include <cmath>

#include "engine/core/rng.h"
#include "tests/material/bsdf_cases.h"

namespace mvpl::material::test {

namespace {

// Mean and standard error of the mean from running sums (values are O(1), doubles suffice).
struct Accumulator {
    double sum = 0.0, sum2 = 0.0;
    void add(double v) {
        sum += v;
        sum2 += v * v;
    }
    Estimate estimate(int n) const {
        const double mean = sum / n;
        const double variance = std::max(0.0, sum2 / n - mean * mean) * n / (n - 1.0);
        return {mean, std::sqrt(variance / n)};
    }
};

}  // namespace

Estimate albedo_uniform(const Bsdf& bsdf, const Vec3& wo, int sample_count, uint64_t seed) {
    Rng rng(seed, 1);
    Accumulator acc;
    for (int i = 0; i < sample_count; ++i) {
        const Vec3 wi = uniform_hemisphere(rng);
        acc.add(luminance(bsdf.eval(wo, wi)) * wi.z * 2.0 * M_PI);
    }
    return acc.estimate(sample_count);
}

Estimate albedo_importance(const Bsdf& bsdf, const Vec3& wo, int sample_count, uint64_t seed) {
    Rng rng(seed, 2);
    Accumulator acc;
    for (int i = 0; i < sample_count; ++i) {
        const Vec2 u(rng.next_float(), rng.next_float());
        const std::optional<BsdfSample> s = bsdf.sample(wo, u, rng.next_float());
        acc.add(s ? luminance(s->weight) : 0.0);
    }
    return acc.estimate(sample_count);
}

}  // namespace mvpl::material::test
