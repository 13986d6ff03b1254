#include "tools/preview/frame_variance.h"

#include <algorithm>
#include <cmath>

#include "engine/core/image_metrics.h"
#include "tools/session/heat_colour.h"

namespace mvpl::preview {

void FrameVariance::reset() {
    m_last = Image();
    m_last_units = 0;
    m_sum = Image();
    m_increments = 0;
}

void FrameVariance::add(const Image& estimate, uint64_t units) {
    const bool same_size =
        m_last.width() == estimate.width() && m_last.height() == estimate.height();
    if (!same_size || units < m_last_units) reset();
    if (m_last_units > 0 && units > m_last_units) {
        if (m_sum.width() != estimate.width()) m_sum = Image(estimate.width(), estimate.height());
        const double n = double(units - m_last_units);
        for (size_t i = 0; i < estimate.pixels().size(); ++i) {
            for (int c = 0; c < 3; ++c) {
                const double l = estimate.pixels()[i][c], last = m_last.pixels()[i][c];
                const double x = (double(units) * l - double(m_last_units) * last) / n;
                m_sum.pixels()[i][c] += float(n * (x - l) * (x - l));
            }
        }
        ++m_increments;
    }
    if (units > m_last_units || m_last_units == 0) {
        m_last = estimate;
        m_last_units = units;
    }
}

Image FrameVariance::relative_error() const {
    Image rel(m_last.width(), m_last.height());
    if (m_increments == 0) return rel;
    for (size_t i = 0; i < rel.pixels().size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            const double variance = m_sum.pixels()[i][c] / double(m_increments);
            const double se = std::sqrt(variance / double(m_last_units));
            const double l = m_last.pixels()[i][c];
            rel.pixels()[i][c] = float(se / std::sqrt(l * l + kRelMseGuard));
        }
    }
    return rel;
}

Image heat_map(const Image& relative_error) {
    Image out(relative_error.width(), relative_error.height());
    for (size_t i = 0; i < out.pixels().size(); ++i) {
        const Rgb& e = relative_error.pixels()[i];
        const float worst = std::max({e.r, e.g, e.b});
        if (!(worst > 0.0f)) continue;
        // t: 0 at 10⁻³, 1 at 1.
        out.pixels()[i] = session::heat_colour((std::log10(worst) + 3.0f) / 3.0f);
    }
    return out;
}

}  // namespace mvpl::preview
