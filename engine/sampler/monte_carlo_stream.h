#pragma once
// The Monte Carlo sampler as a progressive VplStream: next(n) traces the next n light paths of
// the same sequence as MonteCarloSampler::generate (same seed → same VPLs), powers not divided by
// the number of paths; scale() = 1 / paths traced so far.
#include <string>

#include "engine/sampler/light_tracer.h"
#include "engine/sampler/monte_carlo_sampler.h"
#include "engine/sampler/vpl_stream.h"

namespace mvpl::sampler {

class MonteCarloStream final : public VplStream {
public:
    // options.paths is ignored: the stream runs as long as it is asked to.
    MonteCarloStream(const scene::Scene& scene, const trace::Accel& accel,
                     const light::LightSampler& lights, const MonteCarloOptions& options);

    void next(uint64_t work, std::vector<light::Vpl>& out) override;
    double scale() const override { return m_paths > 0 ? 1.0 / double(m_paths) : 0.0; }
    uint64_t work_done() const override { return m_paths; }
    std::string statistics() const override { return {}; }
    std::span<const uint64_t> last_index() const override { return m_index; }
    uint64_t vpls_total() const override { return m_vpls; }

private:
    MonteCarloOptions m_options;
    LightTracer m_tracer;
    bool m_no_lights;
    uint64_t m_paths = 0;
    uint64_t m_vpls = 0;
    std::vector<uint64_t> m_index;
};

}  // namespace mvpl::sampler
