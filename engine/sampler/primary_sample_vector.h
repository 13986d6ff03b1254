#pragma once
// The Metropolis state in primary sample space (Kelemen et al. 2002; pbrt-v3's MLTSampler,
// §16.4.4): a vector u ∈ [0,1)^n read one dimension at a time by the light tracer, so that
// trace(u) is deterministic and mutations act on u, never on the path itself.
//
// Mutations are lazy: each dimension remembers the iteration it was last brought up to date, and
// is only mutated when the tracer reads it. A dimension untouched since a large step gets a fresh
// uniform value; one that missed n small steps gets one step of N(0, n·σ²) — the same wrapped
// distribution as n steps of N(0, σ²), since wrapping to [0,1) commutes with adding. Every
// dimension read in an iteration is backed up first, so that reject() restores u exactly.
#include <cstdint>
#include <vector>

#include "engine/core/rng.h"
#include "engine/sampler/sample_stream.h"

namespace mvpl::sampler {

class PrimarySampleVector final : public SampleStream {
public:
    // Values are drawn from the PCG32 stream (seed, stream); sigma is the small-step width.
    PrimarySampleVector(uint64_t seed, uint64_t stream, float sigma);

    // Iteration 0 is a large step without start_iteration(): the first trace reads a uniform u.
    // Begins iteration i+1 (a proposal): a fresh u (large step) or u + N(0, σ²) per dimension
    // wrapped to [0, 1) (small step), applied lazily as next() reads each dimension from 0 on.
    void start_iteration(bool large_step);
    float next() override;
    // The proposal becomes the state.
    void accept();
    // The state stays what it was before start_iteration(): every dimension read since is
    // restored, values and iteration stamps both.
    void reject();

    // Draws later values from another PCG32 stream (a chain started from a bootstrap path
    // continues on its own stream, so two chains started from the same path do not coincide).
    void reseed(uint64_t seed, uint64_t stream) { m_rng.seed(seed, stream); }

    // The stored value of `dimension` as last brought up to date (tests, debugging).
    float value(size_t dimension) const { return m_x.at(dimension).value; }
    int64_t iteration() const { return m_iteration; }
    size_t dimensions() const { return m_x.size(); }
    float sigma() const { return m_sigma; }

private:
    struct Sample {
        float value = 0.0f;
        int64_t modified = -1;  // iteration the value belongs to; −1: never drawn
        float value_backup = 0.0f;
        int64_t modified_backup = -1;
    };
    void bring_up_to_date(Sample& x);

    Rng m_rng;
    float m_sigma;
    std::vector<Sample> m_x;
    int64_t m_iteration = 0;
    int64_t m_last_large_step = 0;
    bool m_large_step = true;
    size_t m_dimension = 0;
};

// u + s wrapped into [0, 1) — never 1.0f, even where float rounding of u + s − ⌊u + s⌋ would give
// it.
float wrap_unit(double v);

// One standard normal number from two uniforms (Box–Muller).
double standard_normal(Rng& rng);

}  // namespace mvpl::sampler
