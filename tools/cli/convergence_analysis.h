#pragma once
// What `mvpl convergence` concludes from its measurements: each method's error against run time,
// the path tracer's time to reach a VPL method's error, and the error that clamping leaves.
#include <cstdint>
#include <string>
#include <vector>

namespace mvpl::cli {

struct ConvergencePoint {
    std::string method;  // "pt", "mc", "metropolis"
    double seconds = 0.0;
    uint64_t samples = 0;  // spp for the path tracer, VPLs for the VPL methods
    double rel_mse = 0.0;
    double rmse = 0.0;
    double mean_ratio = 1.0;  // mean of the per-channel mean(x) / mean(ref)
};

// An unbiased method's error falls as c/t (variance ∝ 1/samples ∝ 1/time). c is fitted in log
// space with the slope fixed at −1 (the geometric mean of relMSE·t), which does not let the few
// slowest points dominate. Returns 0 without points.
double inverse_time_constant(const std::vector<ConvergencePoint>& points);

// A biased method's error tends to a floor: relMSE(t) ≈ floor + c/t. Least squares in (1/t, e)
// with relative residuals, floor and c kept ≥ 0. The floor is the error that infinitely many
// VPLs would leave — clamping's bias plus whatever else differs from the reference (pixel-centre
// sampling).
struct FloorFit {
    double floor = 0.0;
    double c = 0.0;
};
FloorFit fit_floor(const std::vector<ConvergencePoint>& points);

// The points of one method, in time order.
std::vector<ConvergencePoint> points_of(const std::vector<ConvergencePoint>& all,
                                        const std::string& method);

// CSV with a header line: method,seconds,samples,rel_mse,rmse,mean_ratio.
std::string to_csv(const std::vector<ConvergencePoint>& points);

}  // namespace mvpl::cli
