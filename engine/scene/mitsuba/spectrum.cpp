#include "engine/scene/mitsuba/spectrum.h"

#include <charconv>
#include <cmath>
#include <vector>

#include "engine/scene/mitsuba/properties.h"

namespace mvpl::scene::mitsuba {

namespace {

// Wyman, Sloan & Shirley 2013, eq. 2: a Gaussian with different widths left and right of μ.
double lobe(double lambda, double mu, double sigma_left, double sigma_right) {
    const double t = (lambda - mu) / (lambda < mu ? sigma_left : sigma_right);
    return std::exp(-0.5 * t * t);
}

DVec3 observer(double l) {
    const double x = 1.056 * lobe(l, 599.8, 37.9, 31.0) + 0.362 * lobe(l, 442.0, 16.0, 26.7) -
                     0.065 * lobe(l, 501.1, 20.4, 26.2);
    const double y = 0.821 * lobe(l, 568.8, 46.9, 40.5) + 0.286 * lobe(l, 530.9, 16.3, 31.1);
    const double z = 1.217 * lobe(l, 437.0, 11.8, 36.0) + 0.681 * lobe(l, 459.0, 26.0, 13.8);
    return DVec3(x, y, z);
}

// XYZ → linear Rec.709 (sRGB primaries, D65).
DVec3 xyz_to_rgb(const DVec3& c) {
    return DVec3(3.2404542 * c.x - 1.5371385 * c.y - 0.4985314 * c.z,
                 -0.9692660 * c.x + 1.8760108 * c.y + 0.0415560 * c.z,
                 0.0556434 * c.x - 0.2040259 * c.y + 1.0572252 * c.z);
}

template <class F>
DVec3 project(F&& spectrum) {
    DVec3 xyz(0.0);
    for (double l = 360.0; l <= 830.0; l += 1.0)
        xyz += observer(l) * spectrum(l);
    return xyz_to_rgb(xyz);
}

}  // namespace

Rgb spectrum_to_rgb(const Context& ctx, pugi::xml_node at, const std::string& text) {
    std::vector<double> lambdas, values;
    size_t i = 0;
    while (i < text.size()) {
        if (text[i] == ' ' || text[i] == ',' || text[i] == '\t' || text[i] == '\n' ||
            text[i] == '\r') {
            ++i;
            continue;
        }
        size_t end = i;
        while (end < text.size() && text[end] != ',' && text[end] != ' ' && text[end] != '\t' &&
               text[end] != '\n' && text[end] != '\r')
            ++end;
        const std::string pair = text.substr(i, end - i);
        const size_t colon = pair.find(':');
        double l = 0.0, v = 0.0;
        const auto parse = [&](const std::string& s, double& out) {
            const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
            return ec == std::errc() && ptr == s.data() + s.size() && std::isfinite(out);
        };
        if (colon == std::string::npos || !parse(pair.substr(0, colon), l) ||
            !parse(pair.substr(colon + 1), v))
            ctx.fail(at, "spectrum entry '" + pair + "' is not wavelength:value");
        if (!lambdas.empty() && !(l > lambdas.back()))
            ctx.fail(at, "spectrum wavelengths must increase");
        lambdas.push_back(l);
        values.push_back(v);
        i = end;
    }
    if (lambdas.size() < 2) ctx.fail(at, "a spectrum needs at least two wavelength:value pairs");
    const auto eval = [&](double l) {
        if (l < lambdas.front() || l > lambdas.back()) return 0.0;
        size_t k = 1;
        while (lambdas[k] < l)
            ++k;
        const double t = (l - lambdas[k - 1]) / (lambdas[k] - lambdas[k - 1]);
        return values[k - 1] + t * (values[k] - values[k - 1]);
    };
    const DVec3 rgb = project(eval);
    const DVec3 white = project([](double) { return 1.0; });
    return Rgb(Vec3(rgb / white));
}

}  // namespace mvpl::scene::mitsuba
