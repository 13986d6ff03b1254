#include "tests/material/integrate.h"

#include <algorithm>
#include <cmath>

namespace mvpl::test {

namespace {

// 4-point Gauss-Legendre nodes and weights on [−1, 1]: exact for polynomials of degree 7.
constexpr double kGlNode[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                               0.8611363115940526};
constexpr double kGlWeight[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                                 0.3478548451374538};

double gauss_legendre_2d(const std::function<double(double, double)>& f, double x0, double x1,
                         double y0, double y1) {
    const double hx = 0.5 * (x1 - x0), cx = 0.5 * (x1 + x0);
    const double hy = 0.5 * (y1 - y0), cy = 0.5 * (y1 + y0);
    double sum = 0.0;
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
            sum += kGlWeight[i] * kGlWeight[j] * f(cx + hx * kGlNode[i], cy + hy * kGlNode[j]);
        }
    }
    return sum * hx * hy;
}

double refine(const std::function<double(double, double)>& f, double x0, double x1, double y0,
              double y1, double whole, double tolerance, double rel_tolerance, int forced,
              int depth) {
    const double xm = 0.5 * (x0 + x1), ym = 0.5 * (y0 + y1);
    const double q[4] = {gauss_legendre_2d(f, x0, xm, y0, ym), gauss_legendre_2d(f, xm, x1, y0, ym),
                         gauss_legendre_2d(f, x0, xm, ym, y1),
                         gauss_legendre_2d(f, xm, x1, ym, y1)};
    const double sum = q[0] + q[1] + q[2] + q[3];
    const double error = std::abs(sum - whole);
    const bool converged = error <= tolerance || error <= rel_tolerance * std::abs(sum);
    if (forced <= 0 && (converged || depth <= 0)) return sum;
    // Each quarter gets half of the tolerance (a quarter would bound the sum of the leaves'
    // errors strictly, but never lets the cells along a kink — the horizon, wo·h = 0 — converge;
    // their error shrinks with their area, 4× per level, so half suffices in practice).
    const double t = 0.5 * tolerance;
    const double r = rel_tolerance;
    return refine(f, x0, xm, y0, ym, q[0], t, r, forced - 1, depth - 1) +
           refine(f, xm, x1, y0, ym, q[1], t, r, forced - 1, depth - 1) +
           refine(f, x0, xm, ym, y1, q[2], t, r, forced - 1, depth - 1) +
           refine(f, xm, x1, ym, y1, q[3], t, r, forced - 1, depth - 1);
}

}  // namespace

double integrate_2d(const std::function<double(double, double)>& f, double x0, double x1, double y0,
                    double y1, double abs_tolerance, int initial_splits, double rel_tolerance,
                    int max_depth) {
    return refine(f, x0, x1, y0, y1, gauss_legendre_2d(f, x0, x1, y0, y1), abs_tolerance,
                  rel_tolerance, initial_splits, max_depth);
}

double integrate_hemisphere(const std::function<double(const Vec3&)>& g, double peak_width,
                            double abs_tolerance) {
    const auto integrand = [&g](double theta, double phi) {
        const Vec3 w(static_cast<float>(std::sin(theta) * std::cos(phi)),
                     static_cast<float>(std::sin(theta) * std::sin(phi)),
                     static_cast<float>(std::cos(theta)));
        return g(w) * std::sin(theta);
    };
    const double w = peak_width;
    const double breaks[] = {0.0, 0.5 * w, 2.0 * w, 8.0 * w, 32.0 * w, 0.5 * M_PI};
    double sum = 0.0;
    for (int i = 0; i + 1 < 6; ++i) {
        const double t0 = std::min(breaks[i], 0.5 * M_PI);
        const double t1 = std::min(breaks[i + 1], 0.5 * M_PI);
        if (t1 > t0) sum += integrate_2d(integrand, t0, t1, 0.0, 2.0 * M_PI, abs_tolerance);
    }
    return sum;
}

}  // namespace mvpl::test
