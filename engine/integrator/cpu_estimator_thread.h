#pragma once
// A CPU image that is added to the VPL image — clamping compensation (ClampCompensation,
// issue 13) or caustics (CausticTracer, issue 15) — on a thread of its own, so that its
// passes run while the GPU shades VPL batches rather than after them. The thread runs the passes
// it is allowed and then waits: the render raises the allowance as it shades VPLs, so that the
// CPU's samples keep pace with the VPLs instead of taking the CPU from them.
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>

#include "engine/core/image.h"

namespace mvpl::integrator {

// Compensation passes (samples per pixel) to allow after `vpls` VPLs: one per 32, a default
// shading batch, at most `most`. On the Cornell box at 256² with 2923 VPLs (1024 paths, seed 1),
// 4, 16, 64 and 92 passes left relMSE 1.15·10⁻³, 6.3·10⁻⁴, 5.1·10⁻⁴ and 5.0·10⁻⁴ against
// Mitsuba (docs/results.md); a pass costs about a quarter of a 32-VPL batch's CPU time on
// lavapipe, but on a GPU that shades VPLs a hundred times faster an unbounded count would make
// the CPU the bottleneck of a fixed render, which waits for its passes: kFixedRenderPasses.
uint32_t paced_compensation_passes(uint64_t vpls, uint32_t most = uint32_t(1) << 20);
// Of a job's first `passes` compensation passes, those rank `rank` of `size` runs: every size-th
// from its rank (ClampCompensation's first_pass and pass_stride).
inline uint32_t rank_passes(uint32_t passes, int rank, int size) {
    const auto r = uint32_t(rank), n = uint32_t(size);
    return passes > r ? (passes - r + n - 1) / n : 0;
}
// The most passes a fixed-size render waits for (a time budget waits for none).
inline constexpr uint32_t kFixedRenderPasses = 64;

// What the thread runs passes of: add_pass(), passes() and image(uint32_t*) as ClampCompensation
// and CausticTracer have them.
class PassImage {
public:
    virtual ~PassImage() = default;
    virtual void add_pass() = 0;
    virtual uint32_t passes() const = 0;
    virtual Image image(uint32_t* passes = nullptr) const = 0;
};

template <class Estimator>
class PassImageOf final : public PassImage {
public:
    explicit PassImageOf(std::unique_ptr<Estimator> e) : m_estimator(std::move(e)) {}
    void add_pass() override { m_estimator->add_pass(); }
    uint32_t passes() const override { return m_estimator->passes(); }
    Image image(uint32_t* passes = nullptr) const override { return m_estimator->image(passes); }

private:
    std::unique_ptr<Estimator> m_estimator;
};

class CpuEstimatorThread {
public:
    explicit CpuEstimatorThread(std::unique_ptr<PassImage> passes);
    template <class Estimator>
    explicit CpuEstimatorThread(std::unique_ptr<Estimator> estimator)
        : CpuEstimatorThread(
              std::unique_ptr<PassImage>(new PassImageOf<Estimator>(std::move(estimator)))) {}
    ~CpuEstimatorThread();
    CpuEstimatorThread(const CpuEstimatorThread&) = delete;
    CpuEstimatorThread& operator=(const CpuEstimatorThread&) = delete;

    // Lets the thread run passes until it has done `passes` (never lowers the allowance).
    void allow(uint32_t passes);
    // The compensation image, the mean over its passes (at least one); rethrows what a pass
    // threw. wait: first finish every allowed pass (a fixed render, deterministic for its seed);
    // otherwise stop after the pass under way (a time budget). at_least_one false (a rank's
    // share, which may be none): black when no pass was run.
    Image finish(bool wait, bool at_least_one = true);
    uint32_t passes() const { return m_compensation->passes(); }
    // The mean over the passes completed so far, while the thread goes on; `passes`, if given,
    // receives their count.
    Image snapshot(uint32_t* passes = nullptr) const { return m_compensation->image(passes); }

private:
    void run();

    std::unique_ptr<PassImage> m_compensation;
    std::mutex m_mutex;
    std::condition_variable m_wake;
    uint32_t m_allowed = 0;  // guarded by m_mutex
    bool m_stop = false;     // guarded by m_mutex
    bool m_drain = false;    // guarded by m_mutex: stop once the allowance is spent
    std::exception_ptr m_error;
    std::thread m_thread;
};

}  // namespace mvpl::integrator
