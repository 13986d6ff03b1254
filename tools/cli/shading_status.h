#pragma once
// The render's progress while a chunk is shaded. A chunk holds at least a pool of row-column
// sampling, and a large pool's representatives take long to shade (a pool of 2²⁰ at 128²: a
// minute), during which the bar, which moves between chunks, would stand still and no plain line
// would come. Each batch shaded redraws the bar, or writes the plain line that is due, with the
// VPLs shaded so far after the sampler's own status.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>

#include "engine/core/progress.h"

namespace mvpl::cli {

class ShadingStatus {
public:
    explicit ShadingStatus(Progress& progress) : m_state(std::make_shared<State>()) {
        m_state->progress = &progress;
    }
    // The renderer keeps its options, this callback with them, after the run: from then on it
    // does nothing.
    ~ShadingStatus() {
        std::lock_guard lock(m_state->mutex);
        m_state->progress = nullptr;
    }
    ShadingStatus(const ShadingStatus&) = delete;
    ShadingStatus& operator=(const ShadingStatus&) = delete;

    // For RenderOptions::on_batch (called from the devices' threads).
    std::function<void(size_t)> on_batch() const {
        return [state = m_state](size_t vpls) {
            std::lock_guard lock(state->mutex);
            state->shaded += vpls;
            if (!state->progress) return;
            state->progress->set_status(state->text());
            state->progress->advance(0);
        };
    }

    // The sampler's statistics, after each chunk.
    void set_sampler_status(const std::string& status) {
        std::lock_guard lock(m_state->mutex);
        m_state->sampler = status;
        m_state->progress->set_status(m_state->text());
    }

private:
    struct State {
        std::mutex mutex;
        Progress* progress = nullptr;
        uint64_t shaded = 0;
        std::string sampler;
        std::string text() const {
            return sampler + (sampler.empty() ? "" : "; ") + std::to_string(shaded) +
                   " VPLs shaded";
        }
    };
    std::shared_ptr<State> m_state;
};

}  // namespace mvpl::cli
