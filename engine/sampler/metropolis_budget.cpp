#include "engine/sampler/metropolis_budget.h"

#include <algorithm>
#include <cmath>

namespace mvpl::sampler {

void scale_pool_for_budget(SamplerSettings& settings, double seconds, bool chains_given,
                           bool bootstrap_given) {
    if (!(seconds > kPoolBudgetSeconds)) return;
    const double scale = std::min(std::pow(seconds / kPoolBudgetSeconds, 2.0), kMaxPoolScale);
    if (!chains_given) settings.chains = int(std::lround(double(settings.chains) * scale));
    if (!bootstrap_given) {
        const double grown =
            std::min(std::pow(seconds / kPoolBudgetSeconds, 1.5), kMaxBootstrapScale);
        settings.bootstrap = uint64_t(std::llround(double(settings.bootstrap) * grown));
    }
}

}  // namespace mvpl::sampler
