#pragma once
// A progress bar for long jobs: drawn on stderr only when it is a terminal and the user did not
// ask for --quiet. Thread-safe `advance`; redraws at most ten times a second.
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

private:
    void draw(bool final_line);

    std::string m_label;
    int64_t m_total;
    std::atomic<int64_t> m_done{0};
    bool m_visible;
    bool m_finished = false;
    std::chrono::steady_clock::time_point m_start;
    std::chrono::steady_clock::time_point m_last_draw;
    std::string m_status;
    std::mutex m_mutex;
};

// True when stderr is a terminal.
bool stderr_is_terminal();

}  // namespace mvpl
