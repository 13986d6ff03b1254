#pragma once
// Importance sampling of an environment (scene/environment.h): directions chosen in proportion to
// the map's luminance times sin θ, the piecewise-constant 2D distribution of pbrt-v4's
// ImageInfiniteLight and Mitsuba's envmap (a marginal over rows, a conditional within each), so
// that a small bright region (a sun in a sky map) is found by most samples; a constant
// environment is sampled uniformly over the sphere.
#include <vector>

#include "engine/core/math.h"
#include "engine/scene/environment.h"

namespace mvpl::light {

struct EnvironmentDirection {
    Vec3 w{0.0f};      // unit, towards the environment
    float pdf = 0.0f;  // solid-angle density
};

class EnvironmentSampler {
public:
    EnvironmentSampler() = default;
    explicit EnvironmentSampler(const scene::Environment& environment);

    EnvironmentDirection sample(const Vec2& u) const;
    float pdf(const Vec3& w) const;
    // ∫ luminance(L(ω)) dω over the sphere: the environment's power up to the bounding disk.
    double integrated_luminance() const { return m_integral; }

private:
    const scene::Environment* m_environment = nullptr;
    int m_width = 0;
    int m_height = 0;
    std::vector<double> m_row_cdf;   // height + 1 entries, from 0 to 1
    std::vector<double> m_cdf;       // per row, width + 1 entries each, from 0 to 1
    std::vector<float> m_texel_pdf;  // probability of each texel times width · height
    double m_integral = 0.0;
};

}  // namespace mvpl::light
