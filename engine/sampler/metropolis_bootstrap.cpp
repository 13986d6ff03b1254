#include "engine/sampler/metropolis_bootstrap.h"

#include <algorithm>
#include <span>

#include "engine/core/parallel.h"
#include "engine/sampler/primary_sample_vector.h"
#include "engine/sampler/start_resampling.h"

namespace mvpl::sampler {

// This rank's bootstrap paths: the luminance each path adds to each point is kept, so that the
// relative target's point weights (from the bootstrap's radiance per point) apply without tracing
// twice. Sparse: a path's one VPL lights few of the points (most lie in the other room, behind the
// opening, in the two-room scene), and dense storage grew as paths × points (1 GiB at 2^20 × 256).
struct MetropolisStream::BootstrapPaths {
    struct PointLuminance {
        uint32_t point;
        float value;
    };
    static constexpr uint64_t kBlock = 16;  // paths a block; a block's entries in path order

    BootstrapPaths(uint64_t first, uint64_t count)
        : first(first), count(count), entries_of(count, 0), mine(3 * count, 0.0) {}
    uint64_t blocks() const { return (count + kBlock - 1) / kBlock; }
    // Paths [begin, end) of block b.
    uint64_t block_begin(uint64_t b) const { return b * kBlock; }
    uint64_t block_end(uint64_t b) const { return std::min(count, (b + 1) * kBlock); }
    // Path i's luminance per point, dense, from its block's entries from `at` on.
    void unpack(uint64_t i, size_t& at, const std::vector<PointLuminance>& entries,
                std::vector<float>& dense) const {
        std::fill(dense.begin(), dense.end(), 0.0f);
        for (uint32_t e = 0; e < entries_of[i]; ++e, ++at)
            dense[entries[at].point] = entries[at].value;
    }

    uint64_t first;  // this rank's share [first, first + count) of the paths
    uint64_t count;
    std::vector<std::vector<PointLuminance>> block_entries;
    std::vector<uint32_t> entries_of;  // per path
    // I, [has a VPL] and the start order's key (start_resampling.h) of this rank's paths.
    std::vector<double> mine;
};

MetropolisStream::Bootstrap MetropolisStream::run_bootstrap(const scene::Scene& scene,
                                                            const light::LightSampler& lights,
                                                            cluster::Cluster& ranks, uint64_t n) {
    // Bootstrap: I of n independent paths; path i is what a PrimarySampleVector on stream i
    // reads at iteration 0, so a chain can restart from it exactly.
    // Over ranks, this rank's share [first, first + m) of the paths (all of them on one process).
    const cluster::Share share = cluster::share_of(n, ranks.rank(), ranks.size());
    BootstrapPaths paths(share.first, share.last - share.first);
    const uint64_t m = paths.count;
    const size_t k = m_importance.point_count();
    std::vector<double> radiance(k, 0.0);
    cluster::together(ranks, [&] {
        paths.block_entries.assign(paths.blocks(), {});
        if (!lights.empty() && k > 0) trace_bootstrap(scene.bounds(), paths);
        // In path order, as the dense sum was (zeros left out do not change a sum).
        for (uint64_t b = 0; b < paths.blocks(); ++b) {
            size_t at = 0;
            for (uint64_t i = paths.block_begin(b); i < paths.block_end(b); ++i) {
                for (uint32_t e = 0; e < paths.entries_of[i]; ++e, ++at) {
                    const BootstrapPaths::PointLuminance& entry = paths.block_entries[b][at];
                    radiance[entry.point] += double(entry.value) / double(n);
                }
            }
        }
    });
    ranks.sum_all(radiance);
    Bootstrap bootstrap;
    // On every rank alike (deterministic, a few thousand shadow rays): the point weights then
    // see the whole light, as with the emitter VPLs in the chains' states.
    bootstrap.direct_visible = add_direct_radiance(radiance);
    cluster::together(ranks, [&] {
        m_importance.set_point_radiance(radiance);
        std::vector<float> dense(k);
        for (uint64_t b = 0; b < paths.blocks(); ++b) {
            size_t at = 0;
            for (uint64_t i = paths.block_begin(b); i < paths.block_end(b); ++i) {
                paths.unpack(i, at, paths.block_entries[b], dense);
                paths.mine[i] = m_importance.evaluate(std::span<const float>(dense));
            }
        }
        paths.block_entries = {};
    });
    // Every rank's I, [has a VPL] and key: the whole bootstrap on every rank.
    auto gather = [&](uint64_t part) {
        return ranks.gather_all(std::span<const double>(paths.mine.data() + part * m, size_t(m)));
    };
    bootstrap.importance = gather(0);
    bootstrap.has_vpl = gather(1);
    bootstrap.keys = gather(2);
    return bootstrap;
}

void MetropolisStream::trace_bootstrap(const scene::Bounds& bounds, BootstrapPaths& paths) const {
    const uint64_t m = paths.count;
    const size_t k = m_importance.point_count();
    parallel_for(int64_t(paths.blocks()), 1, [&](int64_t b0, int64_t b1) {
        std::vector<light::Vpl> path;
        std::vector<float> dense(k);
        for (int64_t b = b0; b < b1; ++b) {
            for (uint64_t i = paths.block_begin(uint64_t(b)); i < paths.block_end(uint64_t(b));
                 ++i) {
                PrimarySampleVector u(bootstrap_seed(m_options.seed), paths.first + i,
                                      m_options.sigma);
                trace_state(u, path);
                paths.mine[size_t(m + i)] = path.empty() ? 0.0 : 1.0;
                // The state's (first) VPL's place: exact in a double (30 bits).
                if (!path.empty())
                    paths.mine[size_t(2 * m + i)] = double(morton_key(path[0].position, bounds));
                std::fill(dense.begin(), dense.end(), 0.0f);
                m_importance.evaluate_points(path, dense);
                for (size_t p = 0; p < k; ++p) {
                    if (dense[p] == 0.0f) continue;
                    paths.block_entries[size_t(b)].push_back({uint32_t(p), dense[p]});
                    ++paths.entries_of[i];
                }
            }
        }
    });
}

bool MetropolisStream::add_direct_radiance(std::vector<double>& radiance) const {
    if (!m_direct || radiance.empty()) return false;
    // Enough samples for the point weights (a heuristic of the target: any positive weights keep
    // the estimate unbiased); the sequence's stratification keeps them smooth.
    constexpr uint64_t kSamples = 1024;
    std::vector<light::Vpl> vpl;
    std::vector<float> dense(radiance.size());
    bool lit = false;
    for (uint64_t j = 0; j < kSamples; ++j) {
        vpl.clear();
        if (m_direct->sample(j, vpl) == 0) continue;
        std::fill(dense.begin(), dense.end(), 0.0f);
        m_importance.evaluate_points(vpl, dense);
        for (size_t p = 0; p < radiance.size(); ++p) {
            radiance[p] += double(dense[p]) / double(kSamples);
            lit = lit || dense[p] > 0.0f;
        }
    }
    return lit;
}

}  // namespace mvpl::sampler
