#include "tools/preview/vpl_history.h"

#include <algorithm>

namespace mvpl::preview {
namespace {
// Units per segment at most: a replay after a camera move goes segment by segment, so a big
// one would overrun the frame budget (one path leaves a few VPLs, ~10-40 ms each at 512² on
// lavapipe).
constexpr uint64_t kMaxSegmentWork = 4;
}  // namespace

VplHistory::VplHistory(std::unique_ptr<sampler::VplStream> stream, uint64_t max_work)
    : m_stream(std::move(stream)), m_max_work(max_work) {}

bool VplHistory::exhausted() const {
    return m_max_work > 0 && m_stream->work_done() >= m_max_work;
}

bool VplHistory::ensure(size_t segment, uint64_t work) {
    while (m_segments.size() <= segment) {
        if (exhausted()) return false;
        uint64_t n = std::clamp<uint64_t>(work, 1, kMaxSegmentWork);
        if (m_max_work > 0) n = std::min(n, m_max_work - m_stream->work_done());
        m_stream->next(n, m_vpls);
        m_segments.push_back({m_vpls.size(), m_stream->scale(), n});
    }
    return true;
}

void HistoryReplay::next(uint64_t work, std::vector<light::Vpl>& out) {
    const size_t from = m_history.segment_begin(m_replayed);
    uint64_t drawn = 0;
    while (drawn < work && m_history.ensure(m_replayed, work - drawn)) {
        const VplSegment& segment = m_history.segment(m_replayed++);
        m_scale = segment.scale;
        drawn += segment.work;
    }
    m_work += drawn;
    const std::vector<light::Vpl>& vpls = m_history.vpls();  // after ensure(): it may grow
    out.insert(out.end(), vpls.begin() + std::ptrdiff_t(from),
               vpls.begin() + std::ptrdiff_t(m_history.segment_begin(m_replayed)));
}

}  // namespace mvpl::preview
