#pragma once
// The reference's own share of a relMSE (issue 13, the two-room target). A path-traced reference
// is itself noisy: for an image x, a reference r and the truth t, to first order in the noise
//     E[(x − r)² / (r² + 10⁻²)] ≈ [(x − t)² + Var r] / (t² + 10⁻²),
// so relMSE(x, r) is the image's error plus a constant that no renderer can go below. With M
// independent references of equal sample counts, two of them differ by 2 Var r, and their mean
// carries Var r / M: its share is mean over pairs of relMSE(r_i, r_j) / (2M). Subtracting it
// estimates the error against the truth (docs/results.md, "The reference's own noise").
#include <span>

#include "engine/core/image.h"

namespace mvpl {

// The pixel-wise mean of images of one size (UsageError if they differ or there are none).
Image average_images(std::span<const Image> images);
// The relMSE share of average_images(references): mean over pairs of relMSE / (2M); 0 for one.
double reference_noise(std::span<const Image> references);

}  // namespace mvpl
