#pragma once
// Deterministic numerical integration for the material tests.
#include <functional>

#include "engine/core/math.h"

namespace mvpl::test {

// 2-D adaptive cubature of f over [x0, x1] × [y0, y1]: a 4×4-point Gauss-Legendre rule per cell,
// a cell split in four while the children disagree with the parent by more than both its share of
// `abs_tolerance` and `rel_tolerance` times its integral, after `initial_splits` forced levels (so
// that narrow peaks are not stepped over). The relative bound matters: the integrands are float
// BSDF densities whose rounding noise (~1e-7 relative, more on a narrow lobe whose position is
// rounded) would otherwise never let a cell converge. Returns the integral.
double integrate_2d(const std::function<double(double, double)>& f, double x0, double x1, double y0,
                    double y1, double abs_tolerance, int initial_splits = 2,
                    double rel_tolerance = 1e-4, int max_depth = 12);

// ∫ g(ω) dω over the upper hemisphere in spherical coordinates (θ, φ), with θ split at multiples
// of `peak_width` so that a lobe of that angular width around +z is resolved by the cubature.
double integrate_hemisphere(const std::function<double(const Vec3&)>& g, double peak_width,
                            double abs_tolerance = 1e-7);

}  // namespace mvpl::test
