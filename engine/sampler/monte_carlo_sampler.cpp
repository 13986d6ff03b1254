#include "engine/sampler/monte_carlo_sampler.h"

#include <algorithm>

#include "engine/core/parallel.h"
#include "engine/core/progress.h"
#include "engine/core/rng.h"
#include "engine/core/timer.h"

namespace mvpl::sampler {

namespace {

// Paths per work item: each block is traced in path order into its own vector, and the blocks
// are concatenated in order, so the output is the same whatever thread traced which block.
constexpr uint64_t kBlock = 256;

}  // namespace

MonteCarloSampler::MonteCarloSampler(const scene::Scene& scene, const trace::Accel& accel,
                                     const light::LightSampler& lights)
    : m_scene(scene), m_accel(accel), m_lights(lights) {}

void trace_paths(const LightTracer& tracer, const MonteCarloOptions& options, uint64_t begin,
                 uint64_t end, std::vector<light::Vpl>& out, Progress* progress) {
    if (end <= begin) return;
    const uint64_t seed = mix_bits(options.seed);
    // Streams: 2i for the path's primary samples, 2i + 1 for the One-mode pick.
    const std::vector<float> shifts =
        options.qmc ? halton_shifts(options.seed, options.qmc_dimensions) : std::vector<float>{};
    // Blocks aligned to multiples of kBlock from path 0, so that the split does not depend on
    // where a progressive call starts (only the concatenation order matters, and it is by path).
    const uint64_t first_block = begin / kBlock;
    const uint64_t blocks = (end + kBlock - 1) / kBlock - first_block;
    std::vector<std::vector<light::Vpl>> per_block(blocks);
    parallel_for(int64_t(blocks), 1, [&](int64_t b0, int64_t b1) {
        std::vector<light::Vpl> path;
        for (int64_t b = b0; b < b1; ++b) {
            std::vector<light::Vpl>& block = per_block[size_t(b)];
            const uint64_t lo = std::max(begin, (first_block + uint64_t(b)) * kBlock);
            const uint64_t hi = std::min(end, (first_block + uint64_t(b) + 1) * kBlock);
            for (uint64_t i = lo; i < hi; ++i) {
                path.clear();
                if (options.qmc) {
                    HaltonStream u(i, shifts, seed, 2 * i);
                    tracer.trace(u, path);
                } else {
                    RandomStream u(seed, 2 * i);
                    tracer.trace(u, path);
                }
                if (path.empty()) continue;
                if (options.per_path == VplsPerPath::All) {
                    block.insert(block.end(), path.begin(), path.end());
                } else {
                    Rng pick(seed, 2 * i + 1);
                    const size_t m = path.size();
                    light::Vpl v = path[std::min(m - 1, size_t(pick.next_float() * float(m)))];
                    v.power *= float(m);  // divided by the pick probability 1/m
                    block.push_back(v);
                }
            }
            if (progress) progress->advance();
        }
    });
    size_t total = out.size();
    for (const auto& block : per_block)
        total += block.size();
    out.reserve(total);
    for (auto& block : per_block)
        out.insert(out.end(), block.begin(), block.end());
}

light::VplSet MonteCarloSampler::generate(const MonteCarloOptions& options,
                                          SamplerStats* stats) const {
    Timer timer;
    const uint64_t rays_before = m_accel.ray_count();
    const LightTracer tracer(m_scene, m_accel, m_lights, options.tracer);
    const uint64_t n = options.paths;
    Progress progress("light paths", int64_t((n + kBlock - 1) / kBlock), options.quiet);
    light::VplSet vpls;
    vpls.scale = n > 0 ? 1.0 / double(n) : 0.0;
    if (!m_lights.empty()) trace_paths(tracer, options, 0, n, vpls.vpls, &progress);
    progress.finish();
    if (stats) {
        stats->paths = n;
        stats->vpls = vpls.vpls.size();
        stats->rays = m_accel.ray_count() - rays_before;
        stats->seconds = timer.seconds();
    }
    return vpls;
}

}  // namespace mvpl::sampler
