#include "engine/core/image_metrics.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

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
    constexpr double kGuard = kRelMseGuard;  // the spike metrics', unsquared
    std::vector<double> rel_err(n);
    for (size_t i = 0; i < n; ++i) {
        const DVec3 x(image.pixels()[i]);
        const DVec3 r(reference.pixels()[i]);
        const double lx = double(luminance(image.pixels()[i]));
        const double lr = double(luminance(reference.pixels()[i]));
        rel_err[i] = std::abs(lx - lr) / (std::abs(lr) + kGuard);
        e.max_ratio = std::max(e.max_ratio, lx / (std::abs(lr) + kGuard));
        const DVec3 d = x - r;
        sum_x += x;
        sum_r += r;
        for (int c = 0; c < 3; ++c) {
            rel += d[c] * d[c] / (r[c] * r[c] + kRelMseGuard);
            sq += d[c] * d[c];
            abs_sum += std::abs(d[c]);
        }
    }
    const double count = double(n) * 3.0;
    if (n == 0) return e;
    e.rel_mse = rel / count;
    e.rmse = std::sqrt(sq / count);
    e.mean_abs = abs_sum / count;
    // Nearest rank: the ⌈0.999 n⌉-th smallest.
    const size_t rank = std::min(n - 1, size_t(std::ceil(0.999 * double(n))) - 1);
    std::nth_element(rel_err.begin(), rel_err.begin() + std::ptrdiff_t(rank), rel_err.end());
    e.rel_err_p999 = rel_err[rank];
    for (int c = 0; c < 3; ++c)
        e.mean_ratio[c] =
            sum_r[c] != 0.0 ? sum_x[c] / sum_r[c] : (sum_x[c] == 0.0 ? 1.0 : INFINITY);
    return e;
}

Image crop(const Image& image, int x, int y, int w, int h) {
    if (x < 0 || y < 0 || w < 1 || h < 1 || x > image.width() - w || y > image.height() - h)
        throw UsageError("the region does not lie inside the " + std::to_string(image.width()) +
                         "x" + std::to_string(image.height()) + " image");
    Image out(w, h);
    for (int j = 0; j < h; ++j) {
        for (int i = 0; i < w; ++i)
            out.at(i, j) = image.at(x + i, y + j);
    }
    return out;
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
