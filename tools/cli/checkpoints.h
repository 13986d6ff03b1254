#pragma once
// --write-every SEC (`render`, `reference`): between chunks, once SEC seconds have passed since the
// last write (or the start), the estimate so far is written, so that a long run's files follow
// it. Writing reads the estimate and changes nothing in it.
#include <functional>
#include <utility>

#include "engine/core/timer.h"

namespace mvpl::cli {

class Checkpoints {
public:
    // `every` seconds between writes, 0 for none. `agree` turns this process's answer into the
    // one every rank acts on (rank 0's under mpirun, render_runs.cpp); none: this process's.
    explicit Checkpoints(double every, std::function<bool(bool due)> agree = {})
        : m_every(every), m_agree(std::move(agree)) {}

    // After a chunk: calls `write` when a write is due. Never after the last chunk (`last`),
    // whose image the command writes as its output.
    void after_chunk(bool last, const std::function<void()>& write) {
        if (m_every <= 0.0 || last) return;
        const bool due = m_since.seconds() >= m_every;
        if (!(m_agree ? m_agree(due) : due)) return;
        write();
        m_since.reset();
    }

private:
    double m_every;
    std::function<bool(bool)> m_agree;
    Timer m_since;
};

}  // namespace mvpl::cli
