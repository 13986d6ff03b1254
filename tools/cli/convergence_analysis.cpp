#include "tools/cli/convergence_analysis.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace mvpl::cli {

double inverse_time_constant(const std::vector<ConvergencePoint>& points) {
    double log_sum = 0.0;
    int n = 0;
    for (const ConvergencePoint& p : points) {
        if (p.seconds > 0.0 && p.rel_mse > 0.0) {
            log_sum += std::log(p.rel_mse * p.seconds);
            ++n;
        }
    }
    return n > 0 ? std::exp(log_sum / n) : 0.0;
}

FloorFit fit_floor(const std::vector<ConvergencePoint>& points) {
    // Least squares of e = floor + c·x with x = 1/t, in relative residuals (weights 1/e²): the
    // errors span decades, and in absolute terms the first, start-up-dominated points would
    // decide the fit and the floor would miss the plateau the long runs reach.
    double sw = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
    int n = 0;
    for (const ConvergencePoint& p : points) {
        if (!(p.seconds > 0.0) || !(p.rel_mse > 0.0)) continue;
        const double w = 1.0 / (p.rel_mse * p.rel_mse);
        const double x = 1.0 / p.seconds;
        sw += w;
        sx += w * x;
        sy += w * p.rel_mse;
        sxx += w * x * x;
        sxy += w * x * p.rel_mse;
        ++n;
    }
    FloorFit fit;
    if (n == 0) return fit;
    const double det = sw * sxx - sx * sx;
    const bool solvable = n >= 2 && det > 1e-12 * sw * sxx;
    if (solvable) {
        fit.c = (sw * sxy - sx * sy) / det;
        fit.floor = (sy - fit.c * sx) / sw;
    }
    if (!solvable || fit.c < 0.0) {
        // No decrease to fit: the error is all floor.
        fit.c = 0.0;
        fit.floor = sy / sw;
    } else if (fit.floor < 0.0) {
        // Pure c/t (unbiased): the floor is 0 and c its own least-squares value.
        fit.floor = 0.0;
        fit.c = sxy / sxx;
    }
    return fit;
}

std::vector<ConvergencePoint> points_of(const std::vector<ConvergencePoint>& all,
                                        const std::string& method) {
    std::vector<ConvergencePoint> out;
    for (const ConvergencePoint& p : all) {
        if (p.method == method) out.push_back(p);
    }
    std::sort(out.begin(), out.end(), [](const ConvergencePoint& a, const ConvergencePoint& b) {
        return a.seconds < b.seconds;
    });
    return out;
}

std::string to_csv(const std::vector<ConvergencePoint>& points) {
    std::string csv = "method,seconds,samples,rel_mse,rmse,mean_ratio\n";
    char line[256];
    for (const ConvergencePoint& p : points) {
        std::snprintf(line, sizeof line, "%s,%.6g,%llu,%.6g,%.6g,%.6g\n", p.method.c_str(),
                      p.seconds, static_cast<unsigned long long>(p.samples), p.rel_mse, p.rmse,
                      p.mean_ratio);
        csv += line;
    }
    return csv;
}

}  // namespace mvpl::cli
