#include "tools/preview/preview_stats.h"

#include <algorithm>
#include <cstdarg>
#include <cstdio>

namespace mvpl::preview {
namespace {

// printf's checks apply to the callers' formats (-Wformat under both GCC and clang).
__attribute__((format(printf, 1, 2))) std::string format(const char* fmt, ...) {
    char buf[256];
    va_list args;
    va_start(args, fmt);
    std::vsnprintf(buf, sizeof buf, fmt, args);
    va_end(args);
    return buf;
}

}  // namespace

void PreviewStats::add_vpls(size_t count) {
    m_pending_vpls += count;
    m_total_vpls += count;
}

void PreviewStats::frame_presented(double seconds, double since_start, bool moving) {
    if (m_first_image < 0.0) m_first_image = since_start;
    m_clock = since_start;
    m_recent.push_back({since_start, m_pending_vpls});
    m_pending_vpls = 0;
    while (m_recent.size() > 2 && m_recent.front().time < since_start - 1.0)
        m_recent.pop_front();
    m_last_ms = 1e3 * seconds;
    ++m_frames;
    m_frame_seconds += seconds;
    if (moving) {
        ++m_moving_frames;
        m_moving_seconds += seconds;
        m_moving_worst = std::max(m_moving_worst, seconds);
    }
}

void PreviewStats::moving_phases(double restart, double shading, double present) {
    m_moving_restart += restart;
    m_moving_shading += shading;
    m_moving_present += present;
}

double PreviewStats::vpls_per_second() const {
    if (m_recent.size() < 2) return 0.0;
    size_t vpls = 0;
    for (size_t i = 1; i < m_recent.size(); ++i)
        vpls += m_recent[i].vpls;
    const double span = m_recent.back().time - m_recent.front().time;
    return span > 0.0 ? double(vpls) / span : 0.0;
}

std::vector<std::string> PreviewStats::hud_lines(const HudState& h) const {
    std::vector<std::string> lines;
    lines.push_back(format("%ux%u  sampler %s%s", h.width, h.height, h.sampler.c_str(),
                           h.converged ? "  (converged)" : ""));
    lines.push_back(format("VPLs %zu  (%llu %s)  %.0f VPL/s", h.vpls,
                           static_cast<unsigned long long>(h.work),
                           h.chain ? "chain steps" : "light paths", vpls_per_second()));
    lines.push_back(format("frame %.1f ms  %.1f s since restart  exposure %+.1f", m_last_ms,
                           h.seconds, h.exposure));
    const EstimatorParts& p = h.parts;
    const char* passes = p.moving ? " (at rest)" : "";
    lines.push_back(p.clamp > 0.0f
                        ? format("clamp %.3f x diagonal, %s%s", p.clamp,
                                 p.compensation ? "compensated" : "NOT compensated (darker)",
                                 p.compensation ? passes : "")
                        : format("clamp off"));
    std::string parts = p.caustics ? format("caustics on%s", passes) : "caustics off";
    parts += p.chains ? "  specular chains on" : "  specular chains off";
    parts += p.vsl_radius > 0.0f ? format("  VSL radius %.3f", p.vsl_radius) : "  VSL off (points)";
    if (p.pool > 0)
        parts += format("  row-column: pools of %u VPLs shaded as %u", p.pool, p.clusters);
    lines.push_back(parts);
    if (!h.statistics.empty()) lines.push_back(h.statistics);
    return lines;
}

std::string PreviewStats::summary() const {
    const double fps = m_frame_seconds > 0.0 ? double(m_frames) / m_frame_seconds : 0.0;
    std::string text =
        format("preview: first image after %.3f s; %llu frames, %.1f fps, %zu VPLs shaded",
               m_first_image, static_cast<unsigned long long>(m_frames), fps, m_total_vpls);
    if (m_moving_frames > 0) {
        const double n = double(m_moving_frames);
        text += format(
            "; while moving: %llu frames, %.1f fps (mean %.1f ms: restart %.1f, shading %.1f, "
            "present %.1f; worst %.1f ms)",
            static_cast<unsigned long long>(m_moving_frames), n / m_moving_seconds,
            1e3 * m_moving_seconds / n, 1e3 * m_moving_restart / n, 1e3 * m_moving_shading / n,
            1e3 * m_moving_present / n, 1e3 * m_moving_worst);
    }
    return text;
}

}  // namespace mvpl::preview
