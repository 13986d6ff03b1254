#pragma once
// Small statistics for the tests that compare estimators over independent runs: an image's mean
// luminance over regions, and a sample's mean with its standard error.
#include <cmath>
#include <vector>

#include "engine/core/image.h"

namespace mvpl::test {

// Mean luminance of the whole image and of its four quadrants: five numbers per estimate (a
// bias that moves light between regions shows even where the total is right).
inline std::vector<double> luminance_regions(const Image& image) {
    std::vector<double> r(5, 0.0);
    const int w = image.width(), h = image.height();
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const double l = luminance(image.at(x, y));
            r[0] += l / double(w * h);
            r[1 + (y >= h / 2 ? 2 : 0) + (x >= w / 2 ? 1 : 0)] += 4.0 * l / double(w * h);
        }
    }
    return r;
}

struct MeanAndError {
    double mean = 0.0;
    double standard_error = 0.0;  // of the mean: √(s²/n), s² the unbiased sample variance
};

inline MeanAndError mean_and_error(const std::vector<double>& v) {
    const double n = double(v.size());
    MeanAndError e;
    for (double x : v)
        e.mean += x / n;
    double var = 0.0;
    for (double x : v)
        var += (x - e.mean) * (x - e.mean) / (n - 1.0);
    e.standard_error = std::sqrt(var / n);
    return e;
}

}  // namespace mvpl::test
