// The Metropolis sampler's unbiasedness check (tests/sampler/metropolis_unbiased.h) with each run
// shared by the ranks of `mpirun -np 2` (engine/cluster): their chains start from the combined
// bootstrap and b is summed over them. Every rank runs GoogleTest and checks the same numbers.
#include <gtest/gtest.h>

#include "engine/cluster/cluster.h"
#include "tests/sampler/metropolis_unbiased.h"

namespace mvpl {
namespace {

TEST(MetropolisRanks, UnbiasedOverTwoRanks) {
    ASSERT_EQ(cluster::world().size(), 2) << "run under mpirun -np 2";
    test::expect_metropolis_matches_monte_carlo(cluster::world());
}

}  // namespace
}  // namespace mvpl

int main(int argc, char** argv) {
    const mvpl::cluster::World world(&argc, &argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
