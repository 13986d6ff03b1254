#include "tools/preview/move_recovery.h"

#include <algorithm>
#include <cstdio>

namespace mvpl::preview {

namespace {

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

void MoveRecovery::frame(bool moving, uint64_t sum_vpls, double began, double ended) {
    if (moving) {
        if (!m_moving && m_resting_vpls > 0) m_target = m_resting_vpls;
        m_moving = true;
        return;
    }
    if (m_moving) {  // the first frame at rest after a move
        m_moving = false;
        m_rest_start = began;
        if (m_target > 0) m_first_share.push_back(double(sum_vpls) / double(m_target));
    }
    if (m_target > 0 && double(sum_vpls) >= kRecoveredShare * double(m_target)) {
        m_recovery.push_back(ended - m_rest_start);
        m_target = 0;
    }
    m_resting_vpls = sum_vpls;
}

std::string MoveRecovery::summary() const {
    if (m_first_share.empty()) return "";
    char line[200];
    std::snprintf(line, sizeof line,
                  "after %zu moves: the first frame at rest holds %.0f %% of the resting VPLs "
                  "(median), %.0f %% again after %.2f s (median of %zu)",
                  m_first_share.size(), 100.0 * median(m_first_share), 100.0 * kRecoveredShare,
                  m_recovery.empty() ? 0.0 : median(m_recovery), m_recovery.size());
    return line;
}

}  // namespace mvpl::preview
