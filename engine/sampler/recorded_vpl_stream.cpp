#include "engine/sampler/recorded_vpl_stream.h"

namespace mvpl::sampler {

VplRecording record(VplStream& stream, uint64_t work) {
    VplRecording r;
    stream.next(work, r.vpls);
    const std::span<const uint64_t> index = stream.last_index();
    r.index.assign(index.begin(), index.end());
    r.scale = stream.scale();
    r.work = stream.work_done();
    r.vpls_total = stream.vpls_total();
    return r;
}

void RecordedVplStream::next(uint64_t, std::vector<light::Vpl>& out) {
    m_last = {};
    if (m_given) return;
    m_given = true;
    out.insert(out.end(), m_recording.vpls.begin(), m_recording.vpls.end());
    m_last = m_recording.index;
}

}  // namespace mvpl::sampler
