#pragma once
// PCG32 (O'Neill 2014): small state, good statistics, and independent streams, so that every pixel
// or light path can own a deterministic sequence whatever thread runs it.
#include <cstdint>

namespace mvpl {

class Rng {
public:
    Rng() { seed(0, 0); }
    Rng(uint64_t seed_value, uint64_t stream) { seed(seed_value, stream); }

    void seed(uint64_t seed_value, uint64_t stream) {
        m_state = 0;
        m_inc = (stream << 1u) | 1u;
        next_u32();
        m_state += seed_value;
        next_u32();
    }

    uint32_t next_u32() {
        const uint64_t old = m_state;
        m_state = old * 6364136223846793005ULL + m_inc;
        const uint32_t xorshifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
        const uint32_t rot = static_cast<uint32_t>(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((-rot) & 31u));
    }

    // Uniform in [0, 1): the top 24 bits scaled, so that 1.0f is never returned.
    float next_float() { return static_cast<float>(next_u32() >> 8) * 0x1p-24f; }

private:
    uint64_t m_state = 0;
    uint64_t m_inc = 1;
};

// SplitMix64 finaliser: turns (seed, index) pairs into well-spread stream seeds.
inline uint64_t mix_bits(uint64_t v) {
    v ^= v >> 30;
    v *= 0xbf58476d1ce4e5b9ULL;
    v ^= v >> 27;
    v *= 0x94d049bb133111ebULL;
    v ^= v >> 31;
    return v;
}

}  // namespace mvpl
