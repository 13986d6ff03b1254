#pragma once
// Chi-square goodness-of-fit test of a direction sampler against its claimed density, in the
// style of Mitsuba's and pbrt-v3's BSDF chi² tests: sample directions are histogrammed in
// (cos θ, φ) over the whole sphere, the expected count of each bin is N times the numerically
// integrated pdf (dω = d cos θ dφ), low-expected bins are pooled, and Pearson's statistic is
// compared with the χ² distribution. Samples that fail (nullopt) form one more bin whose expected
// count is N (1 − ∫ pdf), so a sampler that fails more or less often than its pdf says is caught.
#include <cstddef>
#include <functional>
#include <optional>
#include <string>

#include "engine/core/math.h"
#include "tests/material/integrate.h"

namespace mvpl::test {

// Upper tail P(X ≥ statistic) of the χ² distribution with `dof` degrees of freedom
// (the regularised upper incomplete gamma Q(dof/2, statistic/2)).
double chi2_survival(double statistic, int dof);

// Per-test significance for a family of `test_count` tests whose overall significance is
// `family_significance` (Šidák correction).
double sidak_significance(double family_significance, int test_count);

struct Chi2Config {
    int cos_bins = 20;  // over cos θ ∈ [−1, 1]
    int phi_bins = 40;  // over φ ∈ [0, 2π)
    size_t sample_count = 1000000;
    double min_expected = 5.0;   // bins below this are pooled
    double significance = 1e-3;  // per test (apply sidak_significance first)
};

struct Chi2Result {
    bool passed = false;
    double statistic = 0.0;
    int dof = 0;
    double p_value = 0.0;
    double pdf_integral = 0.0;  // ∫ pdf over the sphere, numerically
    size_t failed_samples = 0;
    std::string message;  // why it failed, or a summary
};

// sample(): one direction (unit) or nullopt when the sampler fails; pdf(w): the claimed
// solid-angle density of w. Both must be deterministic for a deterministic test.
Chi2Result run_chi2_test(const std::function<std::optional<Vec3>()>& sample,
                         const std::function<double(const Vec3&)>& pdf, const Chi2Config& config);

}  // namespace mvpl::test
