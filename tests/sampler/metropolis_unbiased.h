#pragma once
// The Metropolis sampler's unbiasedness check (test_metropolis_unbiased.cpp), shareable over the
// ranks of a cluster (tests/cluster/test_metropolis_ranks.cpp runs it under mpirun -np 2).
#include <cstdint>

#include "engine/cluster/cluster.h"

namespace mvpl::test {

// The mean of M independent Metropolis estimates of a small oracle image of the Cornell box
// equals the Monte Carlo mean within a bound derived from the spread of both (GoogleTest
// expectations). Over ranks, every rank calls it: each Metropolis run is shared by the ranks (its
// bootstrap, b and chains; engine/cluster), the regions' luminance summed over them, and every
// rank checks the same numbers.
void expect_metropolis_matches_monte_carlo(cluster::Cluster& ranks);

// The same with other sizes: `runs` estimates each, Metropolis with `chains` chains and `steps`
// steps (Monte Carlo keeps 256 paths), and the chains' starts stratified or independent.
struct UnbiasedCheck {
    int runs = 48;
    int chains = 4;
    uint64_t steps = 256;
    bool stratified_starts = true;
};
void expect_metropolis_matches_monte_carlo(cluster::Cluster& ranks, const UnbiasedCheck& check);

}  // namespace mvpl::test
