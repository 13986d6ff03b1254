#pragma once
// Error of an image against a reference (DESIGN.md "Units and conventions"):
// relMSE = mean((x − r)² / (r² + 10⁻²)), RMSE, mean absolute error, and the ratio of means.
#include "engine/core/image.h"

namespace mvpl {

struct ImageError {
    double rel_mse = 0.0;
    double rmse = 0.0;
    double mean_abs = 0.0;
    DVec3 mean_ratio{1.0};  // per channel mean(x) / mean(r)
};

// Both images must have the same size (throws UsageError otherwise).
ImageError compare_images(const Image& image, const Image& reference);
// Box-downsampling by K×K blocks (the image is cropped to a multiple of K), for comparing
// renderings whose pixel filters differ.
Image block_average(const Image& image, int block);

}  // namespace mvpl
