#include "sampler/monte_carlo_sampler.h"

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

std::vector<light::Vpl> MonteCarloSampler::generate(const MonteCarloOptions& options,
                                                    SamplerStats* stats) const {
    Timer timer;
    const uint64_t rays_before = m_accel.ray_count();
    const LightTracer tracer(m_scene, m_accel, m_lights, options.tracer);
    const uint64_t n = options.paths;
    const float scale = n > 0 ? float(1.0 / double(n)) : 0.0f;
    const uint64_t seed = mix_bits(options.seed);
    // Streams: 2i for the path's primary samples, 2i + 1 for the One-mode pick.
    const std::vector<float> shifts =
        options.qmc ? halton_shifts(options.seed, options.qmc_dimensions) : std::vector<float>{};
    const uint64_t blocks = (n + kBlock - 1) / kBlock;
    std::vector<std::vector<light::Vpl>> per_block(blocks);
    Progress progress("light paths", int64_t(blocks), options.quiet);
    if (!m_lights.empty()) {
        parallel_for(int64_t(blocks), 1, [&](int64_t b0, int64_t b1) {
            std::vector<light::Vpl> path;
            for (int64_t b = b0; b < b1; ++b) {
                std::vector<light::Vpl>& out = per_block[size_t(b)];
                const uint64_t end = std::min(n, uint64_t(b + 1) * kBlock);
                for (uint64_t i = uint64_t(b) * kBlock; i < end; ++i) {
                    path.clear();
                    if (options.qmc) {
                        HaltonStream u(i, shifts, seed, 2 * i);
                        tracer.trace(u, scale, path);
                    } else {
                        RandomStream u(seed, 2 * i);
                        tracer.trace(u, scale, path);
                    }
                    if (path.empty()) continue;
                    if (options.per_path == VplsPerPath::All) {
                        out.insert(out.end(), path.begin(), path.end());
                    } else {
                        Rng pick(seed, 2 * i + 1);
                        const size_t m = path.size();
                        light::Vpl v = path[std::min(m - 1, size_t(pick.next_float() * float(m)))];
                        v.power *= float(m);  // divided by the pick probability 1/m
                        out.push_back(v);
                    }
                }
                progress.advance();
            }
        });
    }
    progress.finish();
    size_t total = 0;
    for (const auto& block : per_block)
        total += block.size();
    std::vector<light::Vpl> vpls;
    vpls.reserve(total);
    for (auto& block : per_block)
        vpls.insert(vpls.end(), block.begin(), block.end());
    if (stats) {
        stats->paths = n;
        stats->vpls = vpls.size();
        stats->rays = m_accel.ray_count() - rays_before;
        stats->seconds = timer.seconds();
    }
    return vpls;
}

}  // namespace mvpl::sampler
