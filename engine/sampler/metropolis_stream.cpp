#include "engine/sampler/metropolis_stream.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <span>

#include "engine/core/parallel.h"
#include "engine/core/rng.h"
#include "engine/core/timer.h"
#include "engine/sampler/metropolis_bootstrap.h"
#include "engine/sampler/primary_sample_vector.h"
#include "engine/sampler/start_resampling.h"

namespace mvpl::sampler {

namespace {

// Independent PCG32 seeds for the chains' uses of randomness, from the user's seed (the
// bootstrap's: metropolis_bootstrap.h).
uint64_t chain_value_seed(uint64_t seed) {
    return mix_bits(seed ^ 0x76616c75ULL);
}
uint64_t chain_step_seed(uint64_t seed) {
    return mix_bits(seed ^ 0x73746570ULL);
}
uint64_t chain_start_seed(uint64_t seed) {
    return mix_bits(seed ^ 0x73746172ULL);
}

// Appends `vpls` with their powers times `factor` (weight · b / I').
void emit(const std::vector<light::Vpl>& vpls, double factor, std::vector<light::Vpl>& out,
          MetropolisStats& stats) {
    if (!(factor > 0.0) || !std::isfinite(factor)) return;
    for (light::Vpl v : vpls) {
        v.power *= float(factor);
        out.push_back(v);
    }
    stats.emitted += vpls.size();
}

}  // namespace

struct MetropolisStream::Chain {
    Chain(uint64_t value_seed, uint64_t stream, float sigma) : u(value_seed, stream, sigma) {}
    PrimarySampleVector u;
    Rng rng;
    std::vector<light::Vpl> current;  // VPLs of the current state, powers as traced
    double current_target = 0.0;      // I'(current) > 0
    double pending = 0.0;             // Σ weight / I' collected by the current state, not emitted
    std::vector<light::Vpl> proposal;
};

MetropolisStream::MetropolisStream(const scene::Scene& scene, const trace::Accel& accel,
                                   const light::LightSampler& lights, const scene::Camera& camera,
                                   const MetropolisOptions& options)
    : m_options(options),
      m_tracer(scene, accel, lights, options.tracer),
      m_direct(options.direct_stride > 0
                   ? std::make_unique<DirectLightSequence>(m_tracer, options.seed)
                   : nullptr),
      m_importance(scene, accel, camera, options.importance) {
    Timer timer;
    m_options.chains = std::max(m_options.chains, 1);
    m_options.large_step = std::clamp(m_options.large_step, 0.0f, 1.0f);
    m_options.defensive = std::max(m_options.defensive, 0.0);
    const uint64_t n = std::max<uint64_t>(m_options.bootstrap, 1);
    cluster::Cluster& ranks = m_options.cluster ? *m_options.cluster : cluster::single_process();
    const Bootstrap bootstrap = run_bootstrap(scene, lights, ranks, n);
    double sum = 0.0;
    uint64_t lit = 0;
    for (uint64_t i = 0; i < n; ++i) {
        sum += bootstrap.importance[i];
        lit += bootstrap.importance[i] > 0.0 ? 1 : 0;
    }
    m_stats.mean_importance = sum / double(n);
    m_stats.bootstrap_lit = lit;
    if (!(m_stats.mean_importance > 0.0) || !std::isfinite(m_stats.mean_importance)) {
        // No chain can start; the direct light's sequence may still light the image.
        m_no_visible_light = !bootstrap.direct_visible;
        m_stats.mean_importance = 0.0;
        m_stats.bootstrap_seconds = timer.seconds();
        return;
    }
    // b = E[I'] and the start distribution ∝ I' (prefix sums for the chains' picks).
    std::vector<double> cdf(n + 1, 0.0);
    for (uint64_t i = 0; i < n; ++i) {
        const double t = defensive_target(bootstrap.importance[i], m_stats.mean_importance,
                                          m_options.defensive, bootstrap.has_vpl[i] != 0.0);
        cdf[i + 1] = cdf[i] + t;
    }
    m_stats.target_sum = cdf[n];
    m_stats.target_count = n;
    m_stats.b = cdf[n] / double(n);
    start_chains(chain_starts(cdf, bootstrap.keys), ranks);
    m_stats.bootstrap_seconds = timer.seconds();
}

std::vector<uint64_t> MetropolisStream::chain_starts(const std::vector<double>& cdf,
                                                     const std::vector<double>& keys) const {
    const uint64_t n = cdf.size() - 1;
    // Chain c's start: stratified (start_resampling.h), or an independent pick ∝ I'.
    std::vector<uint64_t> starts(size_t(m_options.chains), 0);
    if (m_options.stratified_starts) {
        std::vector<double> weights(n);
        for (uint64_t i = 0; i < n; ++i)
            weights[i] = cdf[i + 1] - cdf[i];
        Rng pick(chain_start_seed(m_options.seed), 0);
        return stratified_picks(weights, keys, uint64_t(m_options.chains), pick);
    }
    for (int c = 0; c < m_options.chains; ++c) {
        Rng pick(chain_start_seed(m_options.seed), uint64_t(c));
        const double x = double(pick.next_float()) * cdf[n];
        // The first path whose interval [cdf[i], cdf[i+1]) holds x (empty intervals never do).
        uint64_t start = uint64_t(std::upper_bound(cdf.begin(), cdf.end(), x) - cdf.begin()) - 1;
        start = std::min(start, n - 1);
        while (start > 0 && !(cdf[start + 1] > cdf[start]))
            --start;
        starts[size_t(c)] = start;
    }
    return starts;
}

void MetropolisStream::start_chains(const std::vector<uint64_t>& starts,
                                    const cluster::Cluster& ranks) {
    m_chains.resize(size_t(m_options.chains));
    for (int c = 0; c < m_options.chains; ++c) {
        if (c % ranks.size() != ranks.rank()) continue;  // another rank's chain
        auto chain = std::make_unique<Chain>(bootstrap_seed(m_options.seed), starts[size_t(c)],
                                             m_options.sigma);
        trace_state(chain->u, chain->current);
        chain->current_target = target(chain->current);
        chain->u.reseed(chain_value_seed(m_options.seed), uint64_t(c));
        chain->rng.seed(chain_step_seed(m_options.seed), uint64_t(c));
        m_chains[size_t(c)] = std::move(chain);
    }
}

MetropolisStream::~MetropolisStream() = default;

void MetropolisStream::trace_state(SampleStream& u, std::vector<light::Vpl>& out) const {
    out.clear();
    const bool one = m_options.per_path == VplsPerPath::One;
    const float pick = one ? u.next() : 0.0f;  // dimension 0, before the path's own dimensions
    m_tracer.trace(u, out);
    // The direct light's own sequence carries the emitter VPLs.
    if (m_direct) std::erase_if(out, [](const light::Vpl& v) { return v.path_length == 0; });
    if (!one) return;
    const size_t m = out.size();
    if (m == 0) return;
    const size_t j = std::min(m - 1, size_t(pick * float(m)));
    light::Vpl v = out[j];
    v.power *= float(m);  // divided by the pick probability 1/m
    out.assign(1, v);
}

double MetropolisStream::target(const std::vector<light::Vpl>& vpls) const {
    return defensive_target(m_importance.evaluate(vpls), m_stats.mean_importance,
                            m_options.defensive, !vpls.empty());
}

void MetropolisStream::run_chain(Chain& chain, uint64_t steps, std::vector<light::Vpl>& out,
                                 MetropolisStats& stats) const {
    // Powers carry weight / I'; the normalisation b is applied in scale(), so that it can keep
    // improving with the large steps.
    const double b = 1.0;
    for (uint64_t s = 0; s < steps; ++s) {
        const bool large = chain.rng.next_float() < m_options.large_step;
        stats.large_steps += large ? 1 : 0;
        chain.u.start_iteration(large);
        trace_state(chain.u, chain.proposal);
        const double proposed = chain.proposal.empty() ? 0.0 : target(chain.proposal);
        if (large) {
            // A large step is an independent uniform u: its I' is one more sample of b = E[I'].
            stats.target_sum += proposed;
            ++stats.target_count;
        }
        // current_target > 0 always: the chain starts on a path with I' > 0 and never moves to
        // one with I' = 0 (α = 0 there).
        const double alpha = std::min(1.0, proposed / chain.current_target);
        // Expected values: the current state with 1 − α, the proposal with α.
        chain.pending += (1.0 - alpha) / chain.current_target;
        stats.recorded +=
            (alpha < 1.0 ? chain.current.size() : 0) + (alpha > 0.0 ? chain.proposal.size() : 0);
        if (chain.rng.next_float() < alpha) {
            emit(chain.current, chain.pending * b, out, stats);
            chain.u.accept();
            std::swap(chain.current, chain.proposal);
            chain.current_target = proposed;
            chain.pending = alpha / proposed;  // the proposal's record, merged into the new state
            ++stats.accepted;
        } else {
            chain.u.reject();
            if (alpha > 0.0) emit(chain.proposal, alpha / proposed * b, out, stats);
        }
        ++stats.steps;
    }
    // Everything the steps so far recorded must be in `out` before scale() counts them.
    emit(chain.current, chain.pending * b, out, stats);
    chain.pending = 0.0;
}

void MetropolisStream::next(uint64_t work, std::vector<light::Vpl>& out) {
    m_index.clear();
    if (work == 0) return;
    const uint64_t begin = m_stats.steps;
    const uint64_t end = begin + work;
    if (m_no_visible_light) {
        m_stats.steps = end;
        return;
    }
    if (m_chains.empty()) {  // only the direct light reaches what the camera sees
        m_stats.steps = end;
        next_direct(begin, end, out);
        return;
    }
    cluster::Cluster* ranks = m_options.cluster;
    const bool shared = ranks && ranks->size() > 1;
    const uint64_t chains = m_chains.size();
    // Step t of the run belongs to chain t mod C: chain c's steps in [begin, end).
    auto count_below = [chains](uint64_t t, uint64_t c) {
        return t > c ? (t - c + chains - 1) / chains : 0;
    };
    std::vector<std::vector<light::Vpl>> per_chain(chains);
    std::vector<MetropolisStats> per_stats(chains);
    auto run = [&] {
        parallel_for(int64_t(chains), 1, [&](int64_t c0, int64_t c1) {
            for (int64_t c = c0; c < c1; ++c) {
                if (!m_chains[size_t(c)]) continue;  // another rank's
                const uint64_t steps =
                    count_below(end, uint64_t(c)) - count_below(begin, uint64_t(c));
                run_chain(*m_chains[size_t(c)], steps, per_chain[size_t(c)], per_stats[size_t(c)]);
            }
        });
    };
    std::vector<uint64_t> counts(chains + 5, 0);  // VPLs per chain, then the statistics
    if (!shared) {
        run();
    } else {
        cluster::together(*ranks, run);
    }
    double target_sum = 0.0;  // the large steps' I', summed in chain order as on one process
    for (uint64_t c = 0; c < chains; ++c) {
        counts[c] = per_chain[c].size();
        counts[chains + 0] += per_stats[c].accepted;
        counts[chains + 1] += per_stats[c].large_steps;
        counts[chains + 2] += per_stats[c].recorded;
        counts[chains + 3] += per_stats[c].emitted;
        counts[chains + 4] += per_stats[c].target_count;
        if (shared) {
            target_sum += per_stats[c].target_sum;
        } else {
            m_stats.target_sum += per_stats[c].target_sum;
        }
    }
    if (shared) {
        ranks->sum_all(counts);
        ranks->sum_all(std::span<double>(&target_sum, 1));
    }
    for (uint64_t c = 0, index = m_vpls; c < chains; ++c) {
        if (shared && m_chains[c]) {
            for (size_t i = 0; i < per_chain[c].size(); ++i)
                m_index.push_back(index + i);
        }
        index += counts[c];
        out.insert(out.end(), per_chain[c].begin(), per_chain[c].end());
        m_vpls += counts[c];
    }
    m_stats.steps = end;
    m_stats.accepted += counts[chains + 0];
    m_stats.large_steps += counts[chains + 1];
    m_stats.recorded += counts[chains + 2];
    m_stats.emitted += counts[chains + 3];
    m_stats.target_count += counts[chains + 4];
    m_stats.target_sum += target_sum;
    m_stats.b = m_stats.target_sum / double(std::max<uint64_t>(m_stats.target_count, 1));
    next_direct(begin, end, out);
}

double MetropolisStream::scale() const {
    // b = 1 where no chain runs and only the direct light's sequence lights the image.
    const double b = m_stats.b > 0.0 ? m_stats.b : 1.0;
    return m_stats.steps > 0 ? b / double(m_stats.steps) : 0.0;
}

void MetropolisStream::next_direct(uint64_t begin, uint64_t end, std::vector<light::Vpl>& out) {
    if (!m_direct) return;
    cluster::Cluster* ranks = m_options.cluster;
    const bool shared = ranks && ranks->size() > 1;
    // Powers ÷ b: the renderer multiplies every VPL by scale() = b/N, and the direct estimate is
    // (1/N) Σ steps · P. b is this call's (it changes with the large steps by ≈ 10⁻⁴ a call).
    const double b = m_stats.b > 0.0 ? m_stats.b : 1.0;
    std::vector<light::Vpl> vpl;
    uint64_t index = m_vpls;
    for (const DirectShare& share : direct_shares(begin, end, uint64_t(m_options.direct_stride))) {
        vpl.clear();
        // Every rank evaluates every sample (no rays: a point on a light), so that each knows
        // the whole call's order; sample j is rank j mod R's.
        if (m_direct->sample(share.sample, vpl) == 0) continue;
        if (!shared || int(share.sample % uint64_t(ranks->size())) == ranks->rank()) {
            vpl[0].power *= float(double(share.steps) / b);
            out.push_back(vpl[0]);
            if (shared) m_index.push_back(index);
        }
        ++index;
    }
    m_stats.direct += index - m_vpls;
    m_vpls = index;
}

double MetropolisStream::acceptance() const {
    return m_stats.steps > 0 ? double(m_stats.accepted) / double(m_stats.steps) : 0.0;
}

std::string MetropolisStream::statistics() const {
    if (m_no_visible_light) return "no light reaches what the camera sees";
    char buf[128];
    std::snprintf(buf, sizeof buf, "acceptance %.0f%%, %llu/%llu distinct", 100.0 * acceptance(),
                  static_cast<unsigned long long>(m_stats.emitted),
                  static_cast<unsigned long long>(m_stats.recorded));
    return buf;
}

}  // namespace mvpl::sampler
