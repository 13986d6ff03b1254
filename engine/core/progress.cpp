#include "engine/core/progress.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>

namespace mvpl {

bool stderr_is_terminal() {
    return isatty(fileno(stderr)) != 0;
}

Progress::Progress(std::string label, int64_t total, bool quiet)
    : m_label(std::move(label)),
      m_total(total > 0 ? total : 1),
      m_visible(!quiet && stderr_is_terminal()),
      m_plain(!quiet && !m_visible),
      m_start(std::chrono::steady_clock::now()),
      m_last_draw(m_start) {
    const char* seconds = std::getenv("MVPL_PROGRESS_SECONDS");
    m_plain_seconds = seconds ? std::atof(seconds) : kPlainLineSeconds;
    if (!(m_plain_seconds > 0.0)) m_plain_seconds = kPlainLineSeconds;
}

Progress::~Progress() {
    finish();
}

void Progress::advance(int64_t amount) {
    m_done.fetch_add(amount, std::memory_order_relaxed);
    if (!m_visible && !m_plain) return;
    const auto now = std::chrono::steady_clock::now();
    std::unique_lock lock(m_mutex, std::try_to_lock);
    if (!lock.owns_lock()) return;
    const std::chrono::duration<double> since = now - m_last_draw;
    if (since.count() < (m_visible ? 0.1 : m_plain_seconds)) return;
    m_last_draw = now;
    if (m_visible) {
        draw(false);
    } else {
        write_plain_line();
    }
}

void Progress::write_plain_line() {
    const int64_t done = std::min(m_done.load(std::memory_order_relaxed), m_total);
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
    std::fprintf(stderr, "%s: %.0f%% (%lld/%lld), %.0f s elapsed%s%s\n", m_label.c_str(),
                 100.0 * double(done) / double(m_total), static_cast<long long>(done),
                 static_cast<long long>(m_total), elapsed, m_status.empty() ? "" : "; ",
                 m_status.c_str());
    std::fflush(stderr);
}

void Progress::set_status(const std::string& status) {
    std::lock_guard lock(m_mutex);
    m_status = status;
}

void Progress::finish() {
    std::lock_guard lock(m_mutex);
    if (m_finished) return;
    m_finished = true;
    if (m_visible) draw(true);
}

void Progress::draw(bool final_line) {
    constexpr int kWidth = 30;
    const int64_t done = std::min(m_done.load(std::memory_order_relaxed), m_total);
    const double fraction = double(done) / double(m_total);
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
    const double left = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
    const int filled = int(fraction * kWidth);
    char bar[kWidth + 1];
    for (int i = 0; i < kWidth; ++i)
        bar[i] = i < filled ? '#' : '.';
    bar[kWidth] = '\0';
    std::fprintf(stderr, "\r%s [%s] %5.1f%%  %lld/%lld  %.1fs elapsed, %.1fs left  %s\033[K",
                 m_label.c_str(), bar, 100.0 * fraction, static_cast<long long>(done),
                 static_cast<long long>(m_total), elapsed, left, m_status.c_str());
    if (final_line) std::fputc('\n', stderr);
    std::fflush(stderr);
}

}  // namespace mvpl
