#pragma once
// The CPU oracle (with specular chains) against the path tracer over independent runs, reduced to
// one number per image (the mean over the pixels a test looks at): the comparison of
// tests/reference/test_specular_chain.cpp and test_glass_slab.cpp. Run r uses seed r + 1 for the
// light paths, the chains and the path tracer, so a test is deterministic. The oracle is the
// unbiased one: no clamp, point VPLs.
#include <cstdint>
#include <functional>

#include "engine/core/image.h"
#include "engine/scene/scene.h"
#include "tests/support/sample_statistics.h"

namespace mvpl::test {

struct OracleAgainstTracer {
    int size = 20;  // square images
    int runs = 4;
    int max_depth = 3;
    uint64_t paths = 4096;         // Monte Carlo light paths per oracle run
    int spp = 256;                 // path-tracer samples per pixel per run
    float chain_roughness = 0.2f;  // light::ChainOptions::max_roughness
    // Rotate the sub-pixel lattice per run (subpixel_rotation(seed)), so that the runs' spread
    // also shows the quadrature error over the pixel (features smaller than a pixel).
    bool rotate_subpixel = false;
};

struct OracleTracerMeans {
    MeanAndError oracle;
    MeanAndError tracer;
    double without_chains = 0.0;  // run 0's oracle with chains off
    // σ of the difference of the two independent means.
    double sigma() const;
};

OracleTracerMeans compare_oracle_with_tracer(const scene::Scene& scene,
                                             const OracleAgainstTracer& setup,
                                             const std::function<double(const Image&)>& reduce);

}  // namespace mvpl::test
