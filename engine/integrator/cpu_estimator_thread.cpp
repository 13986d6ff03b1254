#include "engine/integrator/cpu_estimator_thread.h"

#include <algorithm>

namespace mvpl::integrator {

uint32_t paced_compensation_passes(uint64_t vpls, uint32_t most) {
    return uint32_t(std::min<uint64_t>(1 + vpls / 32, most));
}

CpuEstimatorThread::CpuEstimatorThread(std::unique_ptr<PassImage> compensation)
    : m_compensation(std::move(compensation)) {
    m_thread = std::thread([this] { run(); });
}

CpuEstimatorThread::~CpuEstimatorThread() {
    {
        const std::lock_guard lock(m_mutex);
        m_stop = true;
    }
    m_wake.notify_all();
    if (m_thread.joinable()) m_thread.join();
}

void CpuEstimatorThread::allow(uint32_t passes) {
    {
        const std::lock_guard lock(m_mutex);
        m_allowed = std::max(m_allowed, passes);
    }
    m_wake.notify_all();
}

void CpuEstimatorThread::run() {
    try {
        for (;;) {
            {
                std::unique_lock lock(m_mutex);
                m_wake.wait(lock, [&] {
                    return m_stop || m_drain || m_compensation->passes() < m_allowed;
                });
                if (m_stop || m_compensation->passes() >= m_allowed) return;
            }
            m_compensation->add_pass();
        }
    } catch (...) {
        m_error = std::current_exception();
    }
}

Image CpuEstimatorThread::finish(bool wait, bool at_least_one) {
    {
        const std::lock_guard lock(m_mutex);
        if (wait) {
            m_drain = true;
        } else {
            m_stop = true;
        }
    }
    m_wake.notify_all();
    if (m_thread.joinable()) m_thread.join();
    if (m_error) std::rethrow_exception(m_error);
    if (m_compensation->passes() == 0 && at_least_one) m_compensation->add_pass();
    return m_compensation->image();
}

}  // namespace mvpl::integrator
