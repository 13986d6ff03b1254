#pragma once
// The direct light apart from the Metropolis chains (metropolis_stream.h, `direct_stride`).
//
// With one VPL a state, a chain's state is an emitter VPL (path_length 0: direct light) only when
// its pick lands on it, so the emitter VPLs are a random share of the chains' states and their
// number sets the direct light: on the two-room scene at 60 s that light (the floor patch below
// the opening, room A's floor seen through it) carried the image mean's seed-to-seed spread of
// ±1–2 % (docs/results.md, "Direct light apart from the chains"). The integral splits exactly:
// the chains' states keep only the surface VPLs of their paths (path_length ≥ 1), and the emitter
// VPLs come from their own sequence, one per `stride` chain steps, whose emission dimensions are a
// Halton sequence with a random shift per dimension (Cranley–Patterson: every point is uniform, so
// each VPL is an unbiased sample of the direct light, and the points are stratified over the
// light at every prefix: the light's area and the emitters' pick).
#include <cstdint>
#include <vector>

#include "engine/light/vpl.h"
#include "engine/sampler/light_tracer.h"

namespace mvpl::sampler {

class DirectLightSequence {
public:
    // `tracer` must outlive the sequence.
    DirectLightSequence(const LightTracer& tracer, uint64_t seed);

    // Appends sample j's emitter VPL, power as traced (an unbiased estimate of the direct light
    // on its own, like a Monte Carlo path's emitter VPL); returns 0 when the sample misses.
    size_t sample(uint64_t j, std::vector<light::Vpl>& out) const;

private:
    const LightTracer& m_tracer;
    std::vector<float> m_shifts;
    uint64_t m_seed;
};

// Sample j stands for the chain steps [j·stride, (j + 1)·stride): `steps` is how many of them
// lie in [begin, end). A sample whose steps a progressive run's next() calls split is appended
// once in each call with its share, so that after any number of steps N the weights sum to N
// exactly and the direct estimate is (1/N) Σ_t P_{⌊t/stride⌋}.
struct DirectShare {
    uint64_t sample = 0;
    uint64_t steps = 0;
};
std::vector<DirectShare> direct_shares(uint64_t begin, uint64_t end, uint64_t stride);

}  // namespace mvpl::sampler
