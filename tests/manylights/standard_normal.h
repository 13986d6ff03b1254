#pragma once
// A standard normal deviate for the clustering tests' random directions (Box–Muller, the two
// uniforms drawn in order).
#include <cmath>

#include "engine/core/rng.h"

namespace mvpl::manylights_test {

inline float standard_normal(Rng& rng) {
    const double u = 1.0 - double(rng.next_float()), v = double(rng.next_float());
    return float(std::sqrt(-2.0 * std::log(u)) * std::cos(6.283185307179586 * v));
}

}  // namespace mvpl::manylights_test
