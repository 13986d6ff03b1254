#include "sampler/monte_carlo_stream.h"

namespace mvpl::sampler {

MonteCarloStream::MonteCarloStream(const scene::Scene& scene, const trace::Accel& accel,
                                   const light::LightSampler& lights,
                                   const MonteCarloOptions& options)
    : m_options(options),
      m_tracer(scene, accel, lights, options.tracer),
      m_no_lights(lights.empty()) {}

void MonteCarloStream::next(uint64_t work, std::vector<light::Vpl>& out) {
    if (!m_no_lights) trace_paths(m_tracer, m_options, m_paths, m_paths + work, out);
    m_paths += work;
}

}  // namespace mvpl::sampler
