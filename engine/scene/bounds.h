#pragma once
#include <limits>

#include "engine/core/math.h"

namespace mvpl::scene {

// Axis-aligned box; empty until the first point is added.
struct Bounds {
    Vec3 lo{std::numeric_limits<float>::infinity()};
    Vec3 hi{-std::numeric_limits<float>::infinity()};

    void extend(const Vec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    bool empty() const { return !(lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z); }
    Vec3 center() const { return 0.5f * (lo + hi); }
    float diagonal() const { return empty() ? 0.0f : glm::length(hi - lo); }
};

}  // namespace mvpl::scene
