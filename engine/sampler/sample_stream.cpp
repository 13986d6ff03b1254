#include "engine/sampler/sample_stream.h"

#include <algorithm>

namespace mvpl::sampler {

double radical_inverse(uint64_t index, uint32_t base) {
    const double inv_base = 1.0 / double(base);
    double inv = inv_base;
    double result = 0.0;
    while (index > 0) {
        const uint64_t next = index / base;
        result += double(index - next * base) * inv;
        inv *= inv_base;
        index = next;
    }
    return std::min(result, 1.0 - 0x1p-53);
}

const std::vector<uint32_t>& halton_primes() {
    static const std::vector<uint32_t> primes = {2,  3,  5,  7,  11, 13, 17, 19, 23, 29, 31,
                                                 37, 41, 43, 47, 53, 59, 61, 67, 71, 73, 79};
    return primes;
}

std::vector<float> halton_shifts(uint64_t seed, int dimensions) {
    Rng rng(mix_bits(seed), 0x4a17);
    std::vector<float> shifts(size_t(std::max(dimensions, 0)));
    for (float& s : shifts)
        s = rng.next_float();
    return shifts;
}

float HaltonStream::next() {
    const size_t d = m_dimension++;
    if (d >= m_shifts.size() || d >= halton_primes().size()) return m_rng.next_float();
    double v = radical_inverse(m_index, halton_primes()[d]) + double(m_shifts[d]);
    if (v >= 1.0) v -= 1.0;
    // Rounding to float may give exactly 1: keep the half-open interval.
    return std::min(float(v), 0x1.fffffep-1f);
}

}  // namespace mvpl::sampler
