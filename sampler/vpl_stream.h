#pragma once
// A VPL sampler run progressively, the way `mvpl render --time-budget` and `mvpl preview` use it:
// each next() appends the VPLs of `work` more units — light paths for Monte Carlo, chain steps
// for Metropolis — with powers NOT divided by the number of units, so that after any number of
// calls the image is scale() · Σ contributions (the renderer's resolve(scale)). The number of
// units is therefore never needed in advance.
#include <cstdint>
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
};

}  // namespace mvpl::sampler
