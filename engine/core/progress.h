#pragma once
// Progress of a long job on stderr, unless the user asked for --quiet: a bar redrawn at most ten
// times a second on a terminal; otherwise (a pipe, a log file, a batch queue) one plain line
// about every kPlainLineSeconds (MVPL_PROGRESS_SECONDS overrides it). Thread-safe `advance`.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace mvpl {

class Progress {
public:
    Progress(std::string label, int64_t total, bool quiet);
    ~Progress();

    void advance(int64_t amount = 1);
    // Extra text after the bar, e.g. "acceptance 0.41".
    void set_status(const std::string& status);
    void finish();
    bool visible() const { return m_visible; }

    // Seconds between plain lines: frequent enough that a log shows a job is alive, rare enough
    // that an hour's render writes a screenful.
    static constexpr double kPlainLineSeconds = 10.0;

private:
    void draw(bool final_line);
    void write_plain_line();

    std::string m_label;
    int64_t m_total;
    std::atomic<int64_t> m_done{0};
    bool m_visible;
    bool m_plain;                   // not a terminal: plain lines
    double m_plain_seconds = 10.0;  // between them
    bool m_finished = false;
    std::chrono::steady_clock::time_point m_start;
    std::chrono::steady_clock::time_point m_last_draw;
    std::string m_status;
    std::mutex m_mutex;
};

// True when stderr is a terminal.
bool stderr_is_terminal();

}  // namespace mvpl
