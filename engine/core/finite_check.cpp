#include "engine/core/finite_check.h"

#include <cmath>
#include <cstdio>

#include "engine/core/error.h"

namespace mvpl {

NonFiniteReport find_non_finite(const Image& image) {
    NonFiniteReport report;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const Rgb& c = image.at(x, y);
            if (std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2])) continue;
            if (report.pixels++ == 0) {
                report.first_x = x;
                report.first_y = y;
            }
        }
    }
    return report;
}

namespace {

// "N non-finite pixel(s), the first at (x, y) = (r, g, b)"; empty when there are none.
std::string describe_non_finite(const Image& image) {
    const NonFiniteReport report = find_non_finite(image);
    if (report.pixels == 0) return {};
    const Rgb& c = image.at(report.first_x, report.first_y);
    char buf[160];
    std::snprintf(buf, sizeof buf, "%zu non-finite pixel%s, the first at (%d, %d) = (%g, %g, %g)",
                  report.pixels, report.pixels == 1 ? "" : "s", report.first_x, report.first_y,
                  double(c[0]), double(c[1]), double(c[2]));
    return buf;
}

}  // namespace

void require_finite(const Image& image, const std::string& what) {
    const std::string found = describe_non_finite(image);
    if (!found.empty()) throw NonFiniteError(what + ": " + found);
}

Image read_finite_exr(const std::string& path) {
    Image image = read_exr(path);
    const std::string found = describe_non_finite(image);
    if (!found.empty()) throw InputError(path, "holds " + found);
    return image;
}

}  // namespace mvpl
