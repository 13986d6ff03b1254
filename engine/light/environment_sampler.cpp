#include "engine/light/environment_sampler.h"

#include <algorithm>
#include <cmath>

#include "engine/core/sampling.h"

namespace mvpl::light {

namespace {

// The index i with cdf[i] ≤ u < cdf[i + 1] among n intervals, skipping empty ones.
int find_interval(const double* cdf, int n, double u) {
    const double* it = std::upper_bound(cdf, cdf + n + 1, u);
    return std::clamp(int(it - cdf) - 1, 0, n - 1);
}

}  // namespace

EnvironmentSampler::EnvironmentSampler(const scene::Environment& environment)
    : m_environment(&environment) {
    if (!environment.has_map()) {
        m_integral = 4.0 * double(kPi) * double(luminance(environment.radiance));
        return;
    }
    const scene::EnvironmentMap& map = *environment.map;
    m_width = map.width;
    m_height = map.height;
    const double multiplier = double(luminance(environment.radiance));
    std::vector<double> f(size_t(m_width) * size_t(m_height));
    m_row_cdf.assign(size_t(m_height) + 1, 0.0);
    m_cdf.assign(size_t(m_height) * size_t(m_width + 1), 0.0);
    for (int y = 0; y < m_height; ++y) {
        const double sin_theta = std::sin(kPi * (double(y) + 0.5) / double(m_height));
        double* row = &m_cdf[size_t(y) * size_t(m_width + 1)];
        for (int x = 0; x < m_width; ++x) {
            const double value = std::max(0.0, double(luminance(map.at(x, y)))) * sin_theta;
            f[size_t(y) * size_t(m_width) + size_t(x)] = value;
            row[x + 1] = row[x] + value;
        }
        m_row_cdf[size_t(y) + 1] = m_row_cdf[size_t(y)] + row[m_width];
    }
    const double total = m_row_cdf.back();
    // dω = 2π² sin θ du dv, and a texel spans 1/(W H) of the unit square.
    m_integral =
        multiplier * total * 2.0 * double(kPi) * double(kPi) / (double(m_width) * double(m_height));
    m_texel_pdf.assign(f.size(), 0.0f);
    if (!(total > 0.0)) return;
    for (int y = 0; y < m_height; ++y) {
        double* row = &m_cdf[size_t(y) * size_t(m_width + 1)];
        const double row_total = row[m_width];
        for (int x = 0; x <= m_width; ++x)
            row[x] = row_total > 0.0 ? row[x] / row_total : double(x) / double(m_width);
        m_row_cdf[size_t(y) + 1] /= total;
    }
    const double texels = double(m_width) * double(m_height);
    for (size_t i = 0; i < f.size(); ++i)
        m_texel_pdf[i] = float(f[i] / total * texels);
}

EnvironmentDirection EnvironmentSampler::sample(const Vec2& u) const {
    EnvironmentDirection d;
    if (!m_environment) return d;
    if (m_width == 0) {
        d.w = sample_uniform_sphere(u);
        d.pdf = 1.0f / (4.0f * kPi);
        return d;
    }
    const int y = find_interval(m_row_cdf.data(), m_height, double(u.y));
    const double* row = &m_cdf[size_t(y) * size_t(m_width + 1)];
    const int x = find_interval(row, m_width, double(u.x));
    const float texel_pdf = m_texel_pdf[size_t(y) * size_t(m_width) + size_t(x)];
    if (!(texel_pdf > 0.0f)) return d;
    // Uniform within the texel: reuse what is left of u inside the chosen intervals.
    const double dy = m_row_cdf[size_t(y) + 1] - m_row_cdf[size_t(y)];
    const double dx = row[x + 1] - row[x];
    const double fy = dy > 0.0 ? (double(u.y) - m_row_cdf[size_t(y)]) / dy : 0.5;
    const double fx = dx > 0.0 ? (double(u.x) - row[x]) / dx : 0.5;
    const Vec2 uv(float((double(x) + std::clamp(fx, 0.0, 1.0)) / double(m_width)),
                  float((double(y) + std::clamp(fy, 0.0, 1.0)) / double(m_height)));
    float sin_theta = 0.0f;
    d.w = m_environment->uv_to_direction(uv, &sin_theta);
    if (!(sin_theta > 0.0f)) return EnvironmentDirection{};
    d.pdf = texel_pdf / (2.0f * kPi * kPi * sin_theta);
    return d;
}

float EnvironmentSampler::pdf(const Vec3& w) const {
    if (!m_environment) return 0.0f;
    if (m_width == 0) return 1.0f / (4.0f * kPi);
    const Vec2 uv = m_environment->direction_to_uv(w);
    const int x = std::min(int(uv.x * float(m_width)), m_width - 1);
    const int y = std::min(int(uv.y * float(m_height)), m_height - 1);
    const float sin_theta = std::sin(kPi * uv.y);
    if (!(sin_theta > 0.0f)) return 0.0f;
    return m_texel_pdf[size_t(y) * size_t(m_width) + size_t(x)] / (2.0f * kPi * kPi * sin_theta);
}

}  // namespace mvpl::light
