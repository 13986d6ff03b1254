// The Metropolis start pool by time budget (engine/sampler/metropolis_budget.h).
#include <gtest/gtest.h>

#include <cmath>

#include "engine/sampler/metropolis_budget.h"

namespace mvpl::sampler {
namespace {

SamplerSettings scaled(double seconds, bool chains_given = false, bool bootstrap_given = false) {
    SamplerSettings s;
    scale_pool_for_budget(s, seconds, chains_given, bootstrap_given);
    return s;
}

TEST(MetropolisBudget, ShortBudgetsKeepTheDefaults) {
    const MetropolisOptions defaults;
    for (const double seconds : {0.0, 1.0, 8.0, kPoolBudgetSeconds}) {
        EXPECT_EQ(scaled(seconds).chains, defaults.chains) << seconds;
        EXPECT_EQ(scaled(seconds).bootstrap, defaults.bootstrap) << seconds;
    }
}

// 30 s: four times the chains and 2^1.5 the bootstrap; 60 s: sixteen times the chains and eight
// times the bootstrap, the measured setting; longer: no more, which keeps the chains inside
// --chains' range (1..65536). Continuous at 15 s: just above it, both scales are just above 1.
TEST(MetropolisBudget, LongBudgetsScaleThePool) {
    const MetropolisOptions defaults;
    EXPECT_EQ(scaled(30.0).chains, 4 * defaults.chains);
    EXPECT_EQ(scaled(30.0).bootstrap, uint64_t(std::llround(std::pow(2.0, 1.5) * 65536.0)));
    EXPECT_EQ(scaled(60.0).chains, 16 * defaults.chains);
    EXPECT_EQ(scaled(60.0).bootstrap, 8 * defaults.bootstrap);
    EXPECT_EQ(scaled(600.0).chains, 16 * defaults.chains);
    EXPECT_EQ(scaled(600.0).bootstrap, 8 * defaults.bootstrap);
    EXPECT_LE(scaled(1e6).chains, 1 << 16);
    EXPECT_LT(scaled(15.5).bootstrap, uint64_t(1.06 * double(defaults.bootstrap)));
    EXPECT_LT(scaled(15.5).chains, int(1.07 * double(defaults.chains)));
}

TEST(MetropolisBudget, ChosenValuesStay) {
    const MetropolisOptions defaults;
    EXPECT_EQ(scaled(60.0, true, false).chains, defaults.chains);
    EXPECT_EQ(scaled(60.0, true, false).bootstrap, 8 * defaults.bootstrap);
    EXPECT_EQ(scaled(60.0, false, true).chains, 16 * defaults.chains);
    EXPECT_EQ(scaled(60.0, false, true).bootstrap, defaults.bootstrap);
}

}  // namespace
}  // namespace mvpl::sampler
