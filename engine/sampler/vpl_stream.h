#pragma once
// A VPL sampler run progressively, the way `mvpl render --time-budget` and `mvpl preview` use it:
// each next() appends the VPLs of `work` more units — light paths for Monte Carlo, chain steps
// for Metropolis — with powers NOT divided by the number of units, so that after any number of
// calls the image is scale() · Σ contributions (the renderer's resolve(scale)). The number of
// units is therefore never needed in advance.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "engine/light/vpl.h"

namespace mvpl::sampler {

class VplStream {
public:
    virtual ~VplStream() = default;

    // Appends the VPLs of `work` more units to `out` (possibly none: a path may leave no VPL).
    virtual void next(uint64_t work, std::vector<light::Vpl>& out) = 0;
    // The factor that turns the sum of every VPL appended so far into an estimate (1 / units).
    virtual double scale() const = 0;
    // Units done so far.
    virtual uint64_t work_done() const = 0;
    // One short line of sampler statistics for progress bars and summaries
    // (Metropolis: "acceptance 41%, 803/1024 distinct"); may be empty.
    virtual std::string statistics() const = 0;

    // Shared by the ranks of a cluster (engine/cluster; the options' `cluster`), every rank calls
    // next() with the same `work` and appends only its share of the units' VPLs; work_done() and
    // scale() are the whole job's. last_index() then holds each VPL of the last next() call's
    // index in the order one process appends the whole set (increasing), which the renderer's
    // sub-pixel schedule needs; empty on one process: the VPLs follow those before, in order.
    virtual std::span<const uint64_t> last_index() const { return {}; }
    // VPLs appended so far by every rank together.
    virtual uint64_t vpls_total() const = 0;
};

}  // namespace mvpl::sampler
