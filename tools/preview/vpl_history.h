#pragma once
// The VPLs a preview has drawn from its sampler, in segments (one per VplStream::next call) with
// the stream's scale after each, so that any prefix of whole segments is a complete estimate:
// after a camera move the Monte Carlo VPLs are shaded again from the start without tracing them
// again.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "engine/light/vpl.h"
#include "engine/sampler/vpl_stream.h"

namespace mvpl::preview {

struct VplSegment {
    size_t end = 0;      // VPL index one past the segment
    double scale = 0.0;  // the stream's scale() once the segment was drawn
    uint64_t work = 0;   // units it holds
};

class VplHistory {
public:
    // max_work: units after which the stream is asked no more (0: no limit).
    VplHistory(std::unique_ptr<sampler::VplStream> stream, uint64_t max_work);

    // Makes sure `segment + 1` segments exist, drawing `work` more units (at most a few per
    // segment) if needed; false when
    // the stream is exhausted (max_work reached) and the segment does not exist.
    bool ensure(size_t segment, uint64_t work);
    size_t segments() const { return m_segments.size(); }
    const VplSegment& segment(size_t i) const { return m_segments[i]; }
    size_t segment_begin(size_t i) const { return i == 0 ? 0 : m_segments[i - 1].end; }
    const std::vector<light::Vpl>& vpls() const { return m_vpls; }
    bool exhausted() const;
    uint64_t work_done() const { return m_stream->work_done(); }
    std::string statistics() const { return m_stream->statistics(); }

private:
    std::unique_ptr<sampler::VplStream> m_stream;
    uint64_t m_max_work;
    std::vector<light::Vpl> m_vpls;
    std::vector<VplSegment> m_segments;
};

// A history as the VPL stream of one estimate (integrator::VplIntegrator::begin): its segments
// from the first, whole, then new ones drawn as asked, so that any prefix is an estimate.
class HistoryReplay : public sampler::VplStream {
public:
    explicit HistoryReplay(VplHistory& history) : m_history(history) {}

    void next(uint64_t work, std::vector<light::Vpl>& out) override;
    double scale() const override { return m_scale; }
    uint64_t work_done() const override { return m_work; }
    std::string statistics() const override { return m_history.statistics(); }
    uint64_t vpls_total() const override { return m_history.segment_begin(m_replayed); }
    // VPLs the history holds: replayed without sampling (their cubes possibly kept).
    uint64_t vpls_recorded() const { return m_history.vpls().size(); }
    // Every segment replayed and the sampler asked no more: the picture has converged.
    bool converged() const { return m_history.exhausted() && m_replayed == m_history.segments(); }

private:
    VplHistory& m_history;
    size_t m_replayed = 0;  // segments
    uint64_t m_work = 0;
    double m_scale = 0.0;
};

}  // namespace mvpl::preview
