#pragma once
// Private to MetropolisStream (metropolis_stream.cpp, metropolis_bootstrap.cpp). The bootstrap:
// independent paths that give b, the importance's point weights and the chains' start
// distribution. Here the seed of its paths, from which the chains start, and what it hands the
// stream.
#include <cstdint>
#include <vector>

#include "engine/core/rng.h"
#include "engine/sampler/metropolis_stream.h"

namespace mvpl::sampler {

// The bootstrap paths' primary samples: path i reads stream i of this PCG32 seed, independent of
// the chains' (metropolis_stream.cpp), from the user's seed.
inline uint64_t bootstrap_seed(uint64_t seed) {
    return mix_bits(seed ^ 0x626f6f74ULL);
}

// Every rank's bootstrap paths (the whole bootstrap on every rank).
struct MetropolisStream::Bootstrap {
    std::vector<double> importance, has_vpl, keys;  // I, [has a VPL], start order's key
    bool direct_visible = false;                    // the direct light lights an importance point
};

}  // namespace mvpl::sampler
