#pragma once
// Metropolis–Hastings VPL sampling (docs/design.md "The algorithm"; the seed's §3 and §4.4; Segovia
// et al. 2007; primary-sample-space mutations after Kelemen et al. 2002 and pbrt-v3's MLTSampler).
//
// Each of C independent chains walks primary-sample space (PrimarySampleVector) with the target
// I'(x̄) = I(x̄) + ε·mean(I)·[x̄ has a VPL] (importance.h). A step proposes a large step (fresh u)
// with probability β, else a small step u + N(0, σ²) wrapped to [0, 1), and accepts it with
// α = min(1, I'(y)/I'(x)). With the expected-values technique both are recorded: the proposal y
// with weight α, the current x with 1 − α. The chain's density is I'/b, b = E[I'] over independent
// paths, so a state recorded with weight w carries its traced VPL powers times w / I' and over N
// steps in all the image is (b/N)·Σ: scale() = b/N. b is the mean I' of the bootstrap paths and
// of every large-step proposal so far (each an independent uniform u): in a scene where few paths
// reach the camera's view, b's error is a global brightness error, so it keeps improving.
//
// A state is a whole path, or one VPL of it (MetropolisOptions::per_path). By default the chains
// carry the indirect light only (the paths' surface VPLs) and the direct light (emitter VPLs) comes
// from a stratified sequence of its own beside them, one VPL per `direct_stride` steps
// (direct_light.h); its VPLs follow the chains' in each next() call, their powers divided by the
// b of that call, so that scale() = b/N applies to them as well.
//
// Repeats are merged: the weights a state collects while the chain stays on it are summed and its
// VPLs are appended once, when the chain leaves it or at the end of next(). A chain starts from a
// bootstrap path picked in proportion to I' (as pbrt-v3; stratified in space: start_resampling.h),
// then continues on its own random stream.
// The output depends on the seed, the options and the sequence of next() sizes, never on the
// thread count: step t of the run belongs to chain t mod C, and chains append in chain order.
//
// Over a cluster's ranks (options.cluster): rank r of R traces its contiguous share of the
// bootstrap, the per-point radiance is summed over the ranks and the paths' targets gathered, so
// that every rank holds the one-process b and start distribution; the rank runs chains c with
// c mod R = r from them, and the large steps' sums behind b are combined after each next(). The
// ranks' VPLs together are then one process's (same seed, same next() sizes).
//
// If the bootstrap finds I = 0 for every path and the direct light lights none of the points (no
// light reaches what the camera sees), no_visible_light() is true and next() counts work but
// appends nothing: a black image. If only the direct light does, the chains stay idle (no states
// to run from) and the direct light's sequence is the image, with b taken as 1.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "engine/cluster/cluster.h"
#include "engine/light/light_sampler.h"
#include "engine/light/vpl.h"
#include "engine/sampler/direct_light.h"
#include "engine/sampler/importance.h"
#include "engine/sampler/light_tracer.h"
#include "engine/sampler/monte_carlo_sampler.h"
#include "engine/sampler/vpl_stream.h"
#include "engine/scene/scene.h"
#include "engine/trace/accel.h"

namespace mvpl::sampler {

struct MetropolisOptions {
    uint64_t seed = 0;
    // Many short chains: they resample the bootstrap ∝ I' and keep the split between the scene's
    // modes, which few long chains leave to their few starts (two-room, 20 s: relMSE 0.030 with 16
    // chains, 0.0128 with 1024; measured: docs/results.md, "Metropolis defaults", Chains).
    int chains = 1024;
    // β 0.3 with a 65536-path bootstrap beat β 0.1 with 32768: at interactive budgets each chain
    // takes a few steps, and a larger bootstrap has more start states in the rare camera-room mode
    // (measured: docs/results.md, "Metropolis defaults", Large-step probability β).
    float large_step = 0.3f;  // β
    float sigma = 0.01f;      // small-step width in primary sample space
    // Independent paths for b and the chains' starts: cheap next to shading a VPL, and b's error
    // scales the whole image, so the bootstrap is large (docs/results.md, the same section).
    uint64_t bootstrap = 65536;
    // ε of the defensive target: a small ε leaves the VPLs the point set sees badly to rare heavy
    // states, a global brightness error (the mean's error 12% at ε 0.05, 4.5% at 1; measured:
    // docs/results.md, "Metropolis defaults", Defensive ε). ε = 1 spends about half the chains'
    // mass like independent paths and half on the target.
    double defensive = 1.0;
    // One (default): a state is a light path and one of its m VPLs, picked by the primary sample
    // read before the path (dimension 0) and carrying m × its power, so that the target is that
    // VPL's contribution alone (the seed's I(x̄) of the path's end x_k): the chain spends its steps
    // on the VPLs that light the image, not on the direct-light emitter VPL that every path has.
    // All: a state is the whole path with every VPL, the target their sum.
    VplsPerPath per_path = VplsPerPath::One;
    // The chains' starts by systematic resampling of the bootstrap sorted along a space-filling
    // curve of the states' VPLs, not by independent picks (start_resampling.h): every region of
    // the scene gets its expected number of starts to within one.
    bool stratified_starts = true;
    // Chain steps per emitter VPL of the direct light's own sequence (direct_light.h): the
    // chains' states keep only surface VPLs. 0: the chains carry the emitter VPLs too (the seed's
    // sampler). Two-room, 60 s, six seeds: the lit floor patch (a quarter of the image mean, ±6 %
    // before) agrees within 1 % on every seed, and the image mean's spread over seeds fell from
    // 1.3 % to 0.8 %, relMSE from 0.97–1.55 to 0.87–1.04 · 10⁻³ with 8 (docs/results.md,
    // "Direct light apart from the chains"). Cost: one VPL more per 8 steps (≈ 7 % of them).
    int direct_stride = 8;
    LightTracerOptions tracer;
    ImportanceOptions importance;
    // The ranks that share the chains (null: this process alone).
    cluster::Cluster* cluster = nullptr;
};

struct MetropolisStats {
    uint64_t steps = 0;
    uint64_t accepted = 0;
    uint64_t large_steps = 0;
    uint64_t recorded = 0;  // VPLs recorded, repeats counted each time
    uint64_t emitted = 0;   // VPLs appended after merging repeats
    uint64_t direct = 0;    // emitter VPLs of the direct light's sequence appended (every rank)
    double b = 0.0;         // normalisation E[I']: mean I' of the bootstrap and of every large step
    double target_sum = 0.0;    // Σ I' over those independent paths
    uint64_t target_count = 0;  // their number
    double mean_importance = 0.0;
    uint64_t bootstrap_lit = 0;  // bootstrap paths with I > 0
    double bootstrap_seconds = 0.0;
};

class MetropolisStream final : public VplStream {
public:
    // Runs the bootstrap. scene, accel and lights must outlive the stream.
    MetropolisStream(const scene::Scene& scene, const trace::Accel& accel,
                     const light::LightSampler& lights, const scene::Camera& camera,
                     const MetropolisOptions& options);
    ~MetropolisStream() override;

    void next(uint64_t work, std::vector<light::Vpl>& out) override;
    double scale() const override;
    uint64_t work_done() const override { return m_stats.steps; }
    std::string statistics() const override;

    std::span<const uint64_t> last_index() const override { return m_index; }
    uint64_t vpls_total() const override { return m_vpls; }

    bool no_visible_light() const { return m_no_visible_light; }
    const MetropolisStats& stats() const { return m_stats; }
    double acceptance() const;

private:
    struct Chain;
    struct BootstrapPaths;  // metropolis_bootstrap.cpp
    struct Bootstrap;       // metropolis_bootstrap.h
    // I of `n` independent paths (this rank traces its share), the importance's point radiance set
    // from them.
    Bootstrap run_bootstrap(const scene::Scene& scene, const light::LightSampler& lights,
                            cluster::Cluster& ranks, uint64_t n);
    // Traces this rank's bootstrap paths in blocks: their luminance per point, [has a VPL], key.
    void trace_bootstrap(const scene::Bounds& bounds, BootstrapPaths& paths) const;
    // Each chain's start path, from the prefix sums `cdf` of the bootstrap's I' and its keys.
    std::vector<uint64_t> chain_starts(const std::vector<double>& cdf,
                                       const std::vector<double>& keys) const;
    // The chains this rank runs, each on its start path.
    void start_chains(const std::vector<uint64_t>& starts, const cluster::Cluster& ranks);
    void run_chain(Chain& chain, uint64_t steps, std::vector<light::Vpl>& out,
                   MetropolisStats& stats) const;
    double target(const std::vector<light::Vpl>& vpls) const;
    // The state's VPLs from primary samples `u` (per_path decides one or all), powers as traced.
    void trace_state(SampleStream& u, std::vector<light::Vpl>& out) const;
    // The direct light's luminance at each importance point (added to `radiance`), from the first
    // samples of its sequence; true when it lights any point.
    bool add_direct_radiance(std::vector<double>& radiance) const;
    // Appends the direct light's VPLs for steps [begin, end) (this rank's share).
    void next_direct(uint64_t begin, uint64_t end, std::vector<light::Vpl>& out);

    MetropolisOptions m_options;
    LightTracer m_tracer;
    // The direct light's own sequence (null: direct_stride 0, the chains carry it).
    std::unique_ptr<DirectLightSequence> m_direct;
    Importance m_importance;
    // Chain c, or null where another rank runs it.
    std::vector<std::unique_ptr<Chain>> m_chains;
    MetropolisStats m_stats;
    bool m_no_visible_light = false;
    uint64_t m_vpls = 0;  // appended by every rank
    std::vector<uint64_t> m_index;
};

}  // namespace mvpl::sampler
