#pragma once
// Primary samples: the light tracer reads the numbers that decide a light path one dimension at a
// time from a SampleStream, so that the same tracer runs on random numbers, on a quasi-random
// sequence, or (Metropolis) on a stored primary-sample vector u ∈ [0,1)^n.
//
// Dimension layout of a light path (LightTracer): 0 emitter pick, 1–2 point on the emitter, 3–4
// direction of emission, then per bounce 4: BSDF direction (2), lobe (1), Russian roulette (1).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "engine/core/rng.h"

namespace mvpl::sampler {

inline constexpr int kEmissionDimensions = 5;
inline constexpr int kBounceDimensions = 4;

class SampleStream {
public:
    virtual ~SampleStream() = default;
    // The next dimension, uniform in [0, 1).
    virtual float next() = 0;
};

// Independent PCG32 numbers.
class RandomStream final : public SampleStream {
public:
    RandomStream(uint64_t seed, uint64_t stream) : m_rng(seed, stream) {}
    float next() override { return m_rng.next_float(); }

private:
    Rng m_rng;
};

// Radical inverse of `index` in base `base` (van der Corput), in [0, 1).
double radical_inverse(uint64_t index, uint32_t base);

// The first prime numbers, the Halton bases of the first dimensions.
const std::vector<uint32_t>& halton_primes();

// Halton point `index`: dimension d < dimension count is the radical inverse in the d-th prime,
// shifted by shifts[d] modulo 1 (Cranley–Patterson rotation, which keeps every dimension uniform
// and so the estimator unbiased); later dimensions come from a PCG32 stream.
class HaltonStream final : public SampleStream {
public:
    HaltonStream(uint64_t index, const std::vector<float>& shifts, uint64_t seed, uint64_t stream)
        : m_index(index), m_shifts(shifts), m_rng(seed, stream) {}
    float next() override;

private:
    uint64_t m_index;
    const std::vector<float>& m_shifts;
    std::size_t m_dimension = 0;
    Rng m_rng;
};

// One random shift per Halton dimension, from the seed.
std::vector<float> halton_shifts(uint64_t seed, int dimensions);

}  // namespace mvpl::sampler
