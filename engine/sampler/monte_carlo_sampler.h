#pragma once
// Monte Carlo VPL generation: N independent light paths (docs/design.md "The algorithm").
//
// Primary samples are random (PCG32, one stream per path index) or Halton (`qmc`): the first
// `qmc_dimensions` dimensions of path i are the i-th Halton point in the first primes with a
// random Cranley–Patterson shift per dimension from the seed, the rest random. Either way the
// output depends on the seed and the path index only, never on the thread count.
//
// VPLs per path: `All` keeps every VPL of the path with power β (the set's scale is 1/N). `One`
// (the seed report's choice) keeps one VPL picked uniformly among the path's m VPLs with its power
// multiplied by m — divided by its pick probability 1/m — so its expectation equals the sum of All;
// it trades more variance for one VPL (one shadow map) per path.
#include <cstdint>
#include <vector>

#include "engine/cluster/cluster.h"
#include "engine/core/progress.h"
#include "engine/light/light_sampler.h"
#include "engine/light/vpl.h"
#include "engine/sampler/light_tracer.h"
#include "engine/scene/scene.h"
#include "engine/trace/accel.h"

namespace mvpl::sampler {

enum class VplsPerPath { All, One };

// Light paths a render traces when asked for no number (`mvpl render --vpls`).
inline constexpr uint64_t kDefaultPaths = 1024;

struct MonteCarloOptions {
    uint64_t paths = kDefaultPaths;  // N
    uint64_t seed = 0;
    bool qmc = false;
    int qmc_dimensions = kEmissionDimensions + 2 * kBounceDimensions;
    VplsPerPath per_path = VplsPerPath::All;
    LightTracerOptions tracer;
    bool quiet = true;
    // MonteCarloStream only: the ranks that share the paths (null: this process alone).
    cluster::Cluster* cluster = nullptr;
};

struct SamplerStats {
    uint64_t paths = 0;
    uint64_t vpls = 0;
    uint64_t rays = 0;
    double seconds = 0.0;
};

class MonteCarloSampler {
public:
    MonteCarloSampler(const scene::Scene& scene, const trace::Accel& accel,
                      const light::LightSampler& lights);

    // VPLs in path order (within a path, emitter VPL first), powers not divided by N; the set's
    // scale is 1/N (vpl.h).
    light::VplSet generate(const MonteCarloOptions& options, SamplerStats* stats = nullptr) const;

private:
    const scene::Scene& m_scene;
    const trace::Accel& m_accel;
    const light::LightSampler& m_lights;
};

// Appends the VPLs of paths [begin, end) of the sequence that `options` defines (seed, qmc,
// per_path), in path order: generate() and the progressive MonteCarloStream produce the same
// VPLs. Parallel over blocks of paths, deterministic.
void trace_paths(const LightTracer& tracer, const MonteCarloOptions& options, uint64_t begin,
                 uint64_t end, std::vector<light::Vpl>& out, Progress* progress = nullptr);

}  // namespace mvpl::sampler
