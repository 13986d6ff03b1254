// Unbiasedness of the Metropolis VPL sampler on the Cornell box (metropolis_unbiased.h), on one
// process; tests/cluster/test_metropolis_ranks.cpp runs the same check over two MPI ranks.
#include <gtest/gtest.h>

#include "tests/sampler/metropolis_unbiased.h"

namespace mvpl {
namespace {

TEST(MetropolisUnbiased, CornellBoxMatchesMonteCarlo) {
    test::expect_metropolis_matches_monte_carlo(cluster::single_process());
}

}  // namespace
}  // namespace mvpl
