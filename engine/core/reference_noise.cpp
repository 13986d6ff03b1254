#include "engine/core/reference_noise.h"

#include "engine/core/error.h"
#include "engine/core/image_metrics.h"

namespace mvpl {

Image average_images(std::span<const Image> images) {
    if (images.empty()) throw UsageError("no images to average");
    Image mean(images[0].width(), images[0].height());
    for (const Image& image : images) {
        if (image.width() != mean.width() || image.height() != mean.height())
            throw UsageError("the images to average differ in size");
        for (size_t i = 0; i < mean.pixels().size(); ++i)
            mean.pixels()[i] += image.pixels()[i];
    }
    const float inv = 1.0f / float(images.size());
    for (Rgb& p : mean.pixels())
        p *= inv;
    return mean;
}

double reference_noise(std::span<const Image> references) {
    const size_t m = references.size();
    if (m < 2) return 0.0;
    // relMSE(r_i, r_j) ≈ 2 Var r / (t² + 10⁻²) whichever image is the denominator's, to first
    // order; averaging over the pairs uses every reference once as each.
    double sum = 0.0;
    size_t pairs = 0;
    for (size_t i = 0; i < m; ++i) {
        for (size_t j = i + 1; j < m; ++j) {
            sum += compare_images(references[i], references[j]).rel_mse;
            ++pairs;
        }
    }
    return sum / double(pairs) / (2.0 * double(m));
}

}  // namespace mvpl
