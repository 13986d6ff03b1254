#include "tests/material/chi2.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

namespace mvpl::test {

namespace {

// Series of the regularised lower incomplete gamma P(a, x) (Numerical Recipes 6.2.5).
double gamma_p_series(double a, double x) {
    double term = 1.0 / a, sum = term;
    for (int n = 1; n < 10000; ++n) {
        term *= x / (a + n);
        sum += term;
        if (std::abs(term) < std::abs(sum) * 1e-15) break;
    }
    return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

// Continued fraction of the regularised upper incomplete gamma Q(a, x) (modified Lentz,
// Numerical Recipes 6.2.7).
double gamma_q_fraction(double a, double x) {
    constexpr double kTiny = 1e-300;
    double b = x + 1.0 - a, c = 1.0 / kTiny, d = 1.0 / b, h = d;
    for (int i = 1; i < 10000; ++i) {
        const double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::abs(d) < kTiny) d = kTiny;
        c = b + an / c;
        if (std::abs(c) < kTiny) c = kTiny;
        d = 1.0 / d;
        const double delta = d * c;
        h *= delta;
        if (std::abs(delta - 1.0) < 1e-15) break;
    }
    return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}

Vec3 sphere_direction(double cos_theta, double phi) {
    const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
    return Vec3(static_cast<float>(sin_theta * std::cos(phi)),
                static_cast<float>(sin_theta * std::sin(phi)), static_cast<float>(cos_theta));
}

}  // namespace

double chi2_survival(double statistic, int dof) {
    if (dof <= 0) return 1.0;
    if (!(statistic > 0.0)) return 1.0;
    const double a = 0.5 * dof, x = 0.5 * statistic;
    return x < a + 1.0 ? 1.0 - gamma_p_series(a, x) : gamma_q_fraction(a, x);
}

double sidak_significance(double family_significance, int test_count) {
    return 1.0 - std::pow(1.0 - family_significance, 1.0 / std::max(test_count, 1));
}

namespace {

// Histogram of config.sample_count samples over the cos θ × φ bins, the failures in the last
// entry; false (with the reason in `message`) on a non-finite or non-unit direction.
bool histogram(const std::function<std::optional<Vec3>()>& sample, const Chi2Config& config,
               std::vector<double>& observed, std::string& message) {
    const int cells = config.cos_bins * config.phi_bins;
    for (size_t i = 0; i < config.sample_count; ++i) {
        const std::optional<Vec3> w = sample();
        if (!w) {
            ++observed[static_cast<size_t>(cells)];
            continue;
        }
        if (!is_finite(*w) || std::abs(glm::length(*w) - 1.0f) > 1e-3f) {
            message = "sampler returned a non-finite or non-unit direction";
            return false;
        }
        const double phi = std::atan2(static_cast<double>(w->y), static_cast<double>(w->x));
        const double phi01 = (phi < 0.0 ? phi + 2.0 * M_PI : phi) / (2.0 * M_PI);
        const int ci = std::clamp(static_cast<int>((w->z + 1.0) * 0.5 * config.cos_bins), 0,
                                  config.cos_bins - 1);
        const int pi =
            std::clamp(static_cast<int>(phi01 * config.phi_bins), 0, config.phi_bins - 1);
        ++observed[static_cast<size_t>(ci * config.phi_bins + pi)];
    }
    return true;
}

// Expected counts: ∫ pdf over each bin, with an absolute tolerance far below one sample; the
// failure entry gets what the pdf leaves of 1. Returns ∫ pdf over the sphere.
double expected_counts(const std::function<double(const Vec3&)>& pdf, const Chi2Config& config,
                       std::vector<double>& expected) {
    const int cells = config.cos_bins * config.phi_bins;
    const double n = static_cast<double>(config.sample_count);
    const auto density = [&pdf](double cos_theta, double phi) {
        return pdf(sphere_direction(cos_theta, phi));
    };
    const double tolerance = 1e-3 / n;
    const double dc = 2.0 / config.cos_bins, dp = 2.0 * M_PI / config.phi_bins;
    double total = 0.0;
    for (int ci = 0; ci < config.cos_bins; ++ci) {
        for (int pi = 0; pi < config.phi_bins; ++pi) {
            const double integral = integrate_2d(density, -1.0 + ci * dc, -1.0 + (ci + 1) * dc,
                                                 pi * dp, (pi + 1) * dp, tolerance);
            expected[static_cast<size_t>(ci * config.phi_bins + pi)] = integral * n;
            total += integral;
        }
    }
    expected[static_cast<size_t>(cells)] = std::max(0.0, 1.0 - total) * n;
    return total;
}

// The χ² statistic over the bins, those with small expectations (ascending) pooled into one as
// pbrt-v3 does; `used` counts the terms. False where samples fell only in bins of zero
// expectation.
bool pooled_statistic(const std::vector<double>& observed, const std::vector<double>& expected,
                      double min_expected, double& statistic, int& used) {
    std::vector<size_t> order(expected.size());
    std::iota(order.begin(), order.end(), size_t{0});
    std::sort(order.begin(), order.end(),
              [&expected](size_t a, size_t b) { return expected[a] < expected[b]; });
    double pooled_observed = 0.0, pooled_expected = 0.0;
    statistic = 0.0;
    used = 0;
    for (const size_t i : order) {
        if (expected[i] == 0.0 && observed[i] == 0.0) continue;
        const bool pool_open = pooled_expected > 0.0 && pooled_expected < min_expected;
        if (expected[i] < min_expected || pool_open) {
            pooled_observed += observed[i];
            pooled_expected += expected[i];
            continue;
        }
        statistic += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
        ++used;
    }
    if (pooled_expected > 0.0) {
        statistic += (pooled_observed - pooled_expected) * (pooled_observed - pooled_expected) /
                     pooled_expected;
        ++used;
    } else if (pooled_observed > 0.0) {
        return false;
    }
    return true;
}

}  // namespace

Chi2Result run_chi2_test(const std::function<std::optional<Vec3>()>& sample,
                         const std::function<double(const Vec3&)>& pdf, const Chi2Config& config) {
    Chi2Result result;
    const int cells = config.cos_bins * config.phi_bins;
    std::vector<double> observed(static_cast<size_t>(cells) + 1, 0.0);
    std::vector<double> expected(static_cast<size_t>(cells) + 1, 0.0);
    if (!histogram(sample, config, observed, result.message)) return result;
    result.failed_samples = static_cast<size_t>(observed[static_cast<size_t>(cells)]);
    const double total = expected_counts(pdf, config, expected);
    result.pdf_integral = total;

    // A direction bin with no density at all that still receives samples is a support error,
    // whatever the statistic says (the failure bin is exempt: its expectation is a difference).
    for (int i = 0; i < cells; ++i) {
        if (expected[static_cast<size_t>(i)] == 0.0 && observed[static_cast<size_t>(i)] > 0.0) {
            std::ostringstream s;
            s << "bin " << i << " received " << observed[static_cast<size_t>(i)]
              << " samples where the pdf is 0";
            result.message = s.str();
            return result;
        }
    }
    double statistic = 0.0;
    int used = 0;
    if (!pooled_statistic(observed, expected, config.min_expected, statistic, used)) {
        result.message = "samples in bins of zero expectation";
        return result;
    }
    result.statistic = statistic;
    result.dof = used - 1;
    result.p_value = chi2_survival(statistic, result.dof);
    result.passed = result.p_value >= config.significance;
    std::ostringstream s;
    s << "chi2 = " << statistic << ", dof = " << result.dof << ", p = " << result.p_value
      << " (significance " << config.significance << "), integral of pdf = " << total
      << ", failed samples = " << result.failed_samples;
    result.message = s.str();
    return result;
}

}  // namespace mvpl::test
