#include "engine/core/interrupt.h"

#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstring>

namespace mvpl {
namespace {

volatile std::sig_atomic_t g_signal = 0;

// Fixed slots, so that the handler reads them without allocating or locking (only
// async-signal-safe calls there: unlink, _exit). A path longer than a slot is not tracked.
constexpr int kSlots = 16;
constexpr size_t kPathBytes = 4096;
char g_paths[kSlots][kPathBytes];
std::atomic<bool> g_in_use[kSlots];
static_assert(std::atomic<bool>::is_always_lock_free);

extern "C" void on_signal(int signal) {
    if (g_signal == 0) {
        g_signal = signal;
        return;
    }
    for (int i = 0; i < kSlots; ++i) {
        if (g_in_use[i].load()) unlink(g_paths[i]);
    }
    _exit(128 + g_signal);
}

}  // namespace

void install_interrupt_handlers() {
    struct sigaction action {};
    action.sa_handler = on_signal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;  // a read or write under way goes on after the first signal
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
}

bool interrupted() {
    return g_signal != 0;
}

int interrupt_exit_code() {
    return g_signal != 0 ? 128 + int(g_signal) : 0;
}

void track_temporary(const std::string& path) {
    if (path.size() >= kPathBytes) return;
    for (int i = 0; i < kSlots; ++i) {
        if (g_in_use[i].load()) continue;
        std::memcpy(g_paths[i], path.c_str(), path.size() + 1);
        g_in_use[i].store(true);
        return;
    }
}

void untrack_temporary(const std::string& path) {
    for (int i = 0; i < kSlots; ++i) {
        if (g_in_use[i].load() && path == g_paths[i]) {
            g_in_use[i].store(false);
            return;
        }
    }
}

}  // namespace mvpl
