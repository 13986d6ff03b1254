#pragma once
// Error of an image against a reference (docs/design.md "Units and conventions"):
// relMSE = mean((x − r)² / (r² + 10⁻²)), RMSE, mean absolute error, and the ratio of means; and
// the spikes a mean hides (issue 15, "No spikes"): over pixels, with x and r the luminances, the
// 99.9th percentile of |x − r| / (r + 10⁻²) and the largest x / (r + 10⁻²).
#include "engine/core/image.h"

namespace mvpl {

// relMSE's guard against dividing by black pixels: the 10⁻² of r² + 10⁻² (the spike metrics use
// it unsquared).
constexpr double kRelMseGuard = 1e-2;

struct ImageError {
    double rel_mse = 0.0;
    double rmse = 0.0;
    double mean_abs = 0.0;
    DVec3 mean_ratio{1.0};      // per channel mean(x) / mean(r)
    double rel_err_p999 = 0.0;  // 99.9th percentile (nearest rank) of |x − r| / (r + 10⁻²)
    double max_ratio = 0.0;     // max x / (r + 10⁻²)
};

// Both images must have the same size (throws UsageError otherwise).
ImageError compare_images(const Image& image, const Image& reference);
// Box-downsampling by K×K blocks (the image is cropped to a multiple of K), for comparing
// renderings whose pixel filters differ.
Image block_average(const Image& image, int block);
// The w × h pixels from (x, y); the rectangle must lie inside the image (UsageError otherwise).
Image crop(const Image& image, int x, int y, int w, int h);

}  // namespace mvpl
