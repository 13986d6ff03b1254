#include "engine/sampler/direct_light.h"

#include <algorithm>

#include "engine/core/rng.h"
#include "engine/sampler/sample_stream.h"

namespace mvpl::sampler {

DirectLightSequence::DirectLightSequence(const LightTracer& tracer, uint64_t seed)
    : m_tracer(tracer),
      m_shifts(halton_shifts(seed ^ 0x646972656374ULL, kEmissionDimensions)),
      m_seed(mix_bits(seed ^ 0x646972656374ULL)) {}

size_t DirectLightSequence::sample(uint64_t j, std::vector<light::Vpl>& out) const {
    HaltonStream u(j, m_shifts, m_seed, j);
    return m_tracer.trace_emitter(u, out);
}

std::vector<DirectShare> direct_shares(uint64_t begin, uint64_t end, uint64_t stride) {
    std::vector<DirectShare> shares;
    if (stride == 0 || end <= begin) return shares;
    for (uint64_t j = begin / stride; j * stride < end; ++j) {
        const uint64_t lo = std::max(begin, j * stride), hi = std::min(end, (j + 1) * stride);
        shares.push_back({j, hi - lo});
    }
    return shares;
}

}  // namespace mvpl::sampler
