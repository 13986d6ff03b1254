#pragma once
// The running mean of an image estimator's passes (ClampCompensation, CausticTracer): one thread
// adds passes while others read the mean so far, as the renders that run these estimators beside
// the GPU's batches do (engine/integrator/cpu_estimator_thread.h).
#include <cstdint>
#include <mutex>
#include <vector>

#include "engine/core/color.h"
#include "engine/core/image.h"
#include "engine/core/math.h"

namespace mvpl::reference {

class PassMean {
public:
    PassMean(int width, int height)
        : m_width(width), m_height(height), m_sum(size_t(width) * size_t(height), DVec3(0.0)) {}

    uint32_t passes() const {
        const std::lock_guard lock(m_mutex);
        return m_passes;
    }
    // Adds one pass (width × height values, row by row).
    void add(const std::vector<Rgb>& pass) {
        const std::lock_guard lock(m_mutex);
        for (size_t i = 0; i < m_sum.size(); ++i)
            m_sum[i] += DVec3(pass[i]);
        ++m_passes;
    }
    // The mean of the passes added so far (black before the first); `passes`, if given, receives
    // their count, read with the same lock.
    Image mean(uint32_t* passes = nullptr) const {
        Image out(m_width, m_height);
        const std::lock_guard lock(m_mutex);
        if (passes) *passes = m_passes;
        if (m_passes == 0) return out;
        for (size_t i = 0; i < m_sum.size(); ++i)
            out.pixels()[i] = Rgb(m_sum[i] / double(m_passes));
        return out;
    }

private:
    int m_width;
    int m_height;
    mutable std::mutex m_mutex;
    std::vector<DVec3> m_sum;  // per pixel, over the passes
    uint32_t m_passes = 0;
};

}  // namespace mvpl::reference
