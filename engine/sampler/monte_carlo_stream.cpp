#include "engine/sampler/monte_carlo_stream.h"

namespace mvpl::sampler {

MonteCarloStream::MonteCarloStream(const scene::Scene& scene, const trace::Accel& accel,
                                   const light::LightSampler& lights,
                                   const MonteCarloOptions& options)
    : m_options(options),
      m_tracer(scene, accel, lights, options.tracer),
      m_no_lights(lights.empty()) {}

void MonteCarloStream::next(uint64_t work, std::vector<light::Vpl>& out) {
    cluster::Cluster* ranks = m_options.cluster;
    if (!ranks || ranks->size() == 1) {
        const size_t before = out.size();
        if (!m_no_lights) trace_paths(m_tracer, m_options, m_paths, m_paths + work, out);
        m_paths += work;
        m_vpls += out.size() - before;
        return;
    }
    // This rank's paths, then every rank's VPL count: the VPLs of lower ranks come first.
    const size_t before = out.size();
    const cluster::Share mine = cluster::share_of(work, ranks->rank(), ranks->size());
    cluster::together(*ranks, [&] {
        if (!m_no_lights)
            trace_paths(m_tracer, m_options, m_paths + mine.first, m_paths + mine.last, out);
    });
    std::vector<uint64_t> counts(size_t(ranks->size()), 0);
    counts[size_t(ranks->rank())] = out.size() - before;
    ranks->sum_all(counts);
    uint64_t first = m_vpls;
    for (int r = 0; r < ranks->rank(); ++r)
        first += counts[size_t(r)];
    m_index.resize(out.size() - before);
    for (size_t i = 0; i < m_index.size(); ++i)
        m_index[i] = first + i;
    for (const uint64_t c : counts)
        m_vpls += c;
    m_paths += work;
}

}  // namespace mvpl::sampler
