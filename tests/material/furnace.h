#pragma once
// White-furnace estimators of the directional albedo ∫ f(wo, wi) cos θi dωi of a Bsdf, with their
// standard errors.
#include "engine/material/bsdf.h"

namespace mvpl::material::test {

struct Estimate {
    double mean = 0.0;
    double standard_error = 0.0;
};

// Uniform hemisphere sampling of eval (pdf 1 / 2π): independent of the Bsdf's own sampler.
Estimate albedo_uniform(const Bsdf& bsdf, const Vec3& wo, int sample_count, uint64_t seed);
// Average of the sample weights f cos / pdf (failed samples count as 0): uses sample and pdf.
Estimate albedo_importance(const Bsdf& bsdf, const Vec3& wo, int sample_count, uint64_t seed);

}  // namespace mvpl::material::test
