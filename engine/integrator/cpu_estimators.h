#pragma once
// The CPU estimators that run beside the VPL shading, each on a thread of its own
// (cpu_estimator_thread.h): the clamping compensation and the caustic tracer of one estimate,
// paced by the VPLs shaded, summed into the image the VPLs leave out.
#include <cstdint>
#include <memory>

#include "engine/core/image.h"
#include "engine/integrator/cpu_estimator_thread.h"
#include "engine/integrator/estimate.h"
#include "engine/integrator/scene_view.h"

namespace mvpl::integrator {

// How the CPU estimators are paced: a fixed amount of work runs every pass it allowed (at most
// kFixedRenderPasses, deterministic for its seed); open-ended work (a time budget, doubling
// chunks, a window) stops them with the VPLs.
enum class Pacing { Fixed, OpenEnded };

// Whether the estimate's caustic tracer runs on this scene (CausticTracer::active), without
// starting it: then the light tracer leaves no VPL on the chains' class.
bool caustics_needed(const SceneView& view, const Estimate& estimate);

class CpuEstimators {
public:
    // Rank `rank` of `ranks` runs every ranks-th pass from its own (rank_passes), so that
    // together the ranks run one process's passes. Only those the estimate asks for and the
    // scene needs are started (ClampCompensation::active, CausticTracer::active).
    CpuEstimators(const SceneView& view, const Estimate& estimate, int rank = 0, int ranks = 1);

    // Allows the passes due after `vpls` VPLs: the estimate's fixed count, or one per 32 VPLs
    // (paced_compensation_passes), at most kFixedRenderPasses when the pacing is Fixed.
    void pace(uint64_t vpls, Pacing pacing);
    // The sum of the running means so far (black where none runs).
    Image snapshot(int width, int height) const;
    // Finishes both (CpuEstimatorThread::finish: wait for the passes allowed, or stop after the
    // pass under way) and returns the sum of their means.
    Image finish(bool wait, int width, int height);

    // Whether the caustic tracer runs: then the light tracer leaves no VPL on the chains' class.
    bool caustics() const { return m_caustics != nullptr; }
    CpuEstimatorThread* compensation_thread() { return m_compensation.get(); }
    CpuEstimatorThread* caustic_thread() { return m_caustics.get(); }

private:
    uint32_t m_fixed_passes;
    int m_rank, m_ranks;
    std::unique_ptr<CpuEstimatorThread> m_compensation;
    std::unique_ptr<CpuEstimatorThread> m_caustics;
};

}  // namespace mvpl::integrator
