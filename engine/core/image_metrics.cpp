#include "engine/core/image_metrics.h"

#include <string>

#include "engine/core/error.h"

namespace mvpl {

ImageError compare_images(const Image& image, const Image& reference) {
    if (image.width() != reference.width() || image.height() != reference.height()) {
        throw UsageError("images differ in size: " + std::to_string(image.width()) + "x" +
                         std::to_string(image.height()) + " against " +
                         std::to_string(reference.width()) + "x" +
                         std::to_string(reference.height()));
    }
    ImageError e;
    DVec3 sum_x(0.0), sum_r(0.0);
    double rel = 0.0, sq = 0.0, abs_sum = 0.0;
    const size_t n = image.pixels().size();
    for (size_t i = 0; i < n; ++i) {
        const DVec3 x(image.pixels()[i]);
        const DVec3 r(reference.pixels()[i]);
        const DVec3 d = x - r;
        sum_x += x;
        sum_r += r;
        for (int c = 0; c < 3; ++c) {
            rel += d[c] * d[c] / (r[c] * r[c] + 1e-2);
            sq += d[c] * d[c];
            abs_sum += std::abs(d[c]);
        }
    }
    const double count = double(n) * 3.0;
    if (n == 0) return e;
    e.rel_mse = rel / count;
    e.rmse = std::sqrt(sq / count);
    e.mean_abs = abs_sum / count;
    for (int c = 0; c < 3; ++c)
        e.mean_ratio[c] =
            sum_r[c] != 0.0 ? sum_x[c] / sum_r[c] : (sum_x[c] == 0.0 ? 1.0 : INFINITY);
    return e;
}

Image block_average(const Image& image, int block) {
    if (block <= 1) return image;
    const int w = image.width() / block;
    const int h = image.height() / block;
    Image out(w, h);
    const double inv = 1.0 / (double(block) * block);
    for (int by = 0; by < h; ++by) {
        for (int bx = 0; bx < w; ++bx) {
            DVec3 sum(0.0);
            for (int y = 0; y < block; ++y) {
                for (int x = 0; x < block; ++x)
                    sum += DVec3(image.at(bx * block + x, by * block + y));
            }
            out.at(bx, by) = Rgb(sum * inv);
        }
    }
    return out;
}

}  // namespace mvpl
