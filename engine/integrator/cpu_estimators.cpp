#include "engine/integrator/cpu_estimators.h"

namespace mvpl::integrator {

CpuEstimators::CpuEstimators(const SceneView& v, const Estimate& estimate, int rank, int ranks)
    : m_fixed_passes(estimate.compensation_passes), m_rank(rank), m_ranks(ranks) {
    if (estimate.compensate) {
        CompensationOptions options = compensation_options(estimate);
        options.camera = v.camera;
        options.first_pass = uint32_t(rank);
        options.pass_stride = uint32_t(ranks);
        auto compensation =
            std::make_unique<ClampCompensation>(*v.scene, *v.accel, *v.lights, options);
        if (compensation->active())
            m_compensation = std::make_unique<CpuEstimatorThread>(std::move(compensation));
    }
    if (estimate.caustics) {
        CausticOptions options = caustic_options(estimate);
        options.camera = v.camera;
        options.first_pass = uint32_t(rank);
        options.pass_stride = uint32_t(ranks);
        auto caustics = std::make_unique<CausticTracer>(*v.scene, *v.accel, *v.lights, options);
        if (caustics->active())
            m_caustics = std::make_unique<CpuEstimatorThread>(std::move(caustics));
    }
    if (m_fixed_passes > 0) pace(0, Pacing::Fixed);
}

bool caustics_needed(const SceneView& v, const Estimate& estimate) {
    return estimate.caustics &&
           CausticTracer(*v.scene, *v.accel, *v.lights, caustic_options(estimate)).active();
}

void CpuEstimators::pace(uint64_t vpls, Pacing pacing) {
    const uint32_t most = pacing == Pacing::Fixed ? kFixedRenderPasses : uint32_t(1) << 20;
    const uint32_t passes =
        m_fixed_passes > 0 ? m_fixed_passes : paced_compensation_passes(vpls, most);
    const uint32_t mine = rank_passes(passes, m_rank, m_ranks);
    if (m_compensation) m_compensation->allow(mine);
    if (m_caustics) m_caustics->allow(mine);
}

Image CpuEstimators::snapshot(int width, int height) const {
    Image sum(width, height);
    for (const CpuEstimatorThread* thread : {m_compensation.get(), m_caustics.get()}) {
        if (!thread) continue;
        const Image part = thread->snapshot();
        for (size_t i = 0; i < sum.pixels().size(); ++i)
            sum.pixels()[i] += part.pixels()[i];
    }
    return sum;
}

Image CpuEstimators::finish(bool wait, int width, int height) {
    Image sum(width, height);
    for (CpuEstimatorThread* thread : {m_compensation.get(), m_caustics.get()}) {
        if (!thread) continue;
        const Image part = thread->finish(wait);
        for (size_t i = 0; i < sum.pixels().size(); ++i)
            sum.pixels()[i] += part.pixels()[i];
    }
    return sum;
}

}  // namespace mvpl::integrator
