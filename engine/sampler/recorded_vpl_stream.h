#pragma once
// VPLs sampled once and shaded many times: `mvpl bench` renders one set with each configuration
// it measures. The stream gives the recording whole at its first next(), whatever the work asked,
// and nothing after.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "engine/light/vpl.h"
#include "engine/sampler/vpl_stream.h"

namespace mvpl::sampler {

// What a stream appended in one next() call, with what its accessors said after it.
struct VplRecording {
    std::vector<light::Vpl> vpls;
    std::vector<uint64_t> index;  // VplStream::last_index(): empty on one process
    double scale = 0.0;
    uint64_t work = 0;
    uint64_t vpls_total = 0;  // by every rank
};

// `work` units of `stream` (a fresh one), recorded.
VplRecording record(VplStream& stream, uint64_t work);

class RecordedVplStream final : public VplStream {
public:
    // The recording must outlive the stream.
    explicit RecordedVplStream(const VplRecording& recording) : m_recording(recording) {}

    void next(uint64_t work, std::vector<light::Vpl>& out) override;
    double scale() const override { return m_given ? m_recording.scale : 0.0; }
    uint64_t work_done() const override { return m_given ? m_recording.work : 0; }
    std::string statistics() const override { return {}; }
    std::span<const uint64_t> last_index() const override { return m_last; }
    uint64_t vpls_total() const override { return m_given ? m_recording.vpls_total : 0; }

private:
    const VplRecording& m_recording;
    bool m_given = false;
    std::span<const uint64_t> m_last;
};

}  // namespace mvpl::sampler
