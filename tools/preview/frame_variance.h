#pragma once
// The preview's error view: each pixel's relative standard error, estimated from how the running
// estimate changes between frames. After N units (light paths) the estimate is L_N; between two
// reads the n = N − N' new units alone estimate X = (N·L_N − N'·L_N') / n, whose variance is
// σ²/n for the per-unit variance σ² of Monte Carlo paths (independent between frames). So
// n·(X − L)² averages to σ² over the reads, and the estimate's standard error is √(σ²/N). Shown
// relative as mvpl compare's relMSE weighs it: se / √(L² + 10⁻²) per channel, so that the
// picture's mean square estimates the VPLs' share of the relMSE against the converged image:
// not the bias (the clamp's), not the error of too few sub-pixel positions (frames share them),
// and less than all of a Metropolis chain's (its frames are correlated). Measured on the Cornell
// box at 48×32 without jitter: 0.87× the actual relMSE summed over three seeds
// (tests/window/test_preview_error_view.cpp).
#include <cstdint>

#include "engine/core/image.h"

namespace mvpl::preview {

class FrameVariance {
public:
    // A new sum began: forget the reads.
    void reset();
    // A read of the running estimate after `units` units of it.
    void add(const Image& estimate, uint64_t units);
    // Relative standard error per pixel and channel (black before two reads).
    Image relative_error() const;
    // Reads whose increments entered σ².
    uint32_t increments() const { return m_increments; }

private:
    Image m_last;  // the estimate at the last read
    uint64_t m_last_units = 0;
    Image m_sum;  // Σ n·(X − L)² per pixel and channel
    uint32_t m_increments = 0;
};

// The relative errors as colours: log₁₀ from 10⁻³ (blue) through 10⁻² (green) and 10⁻¹ (yellow)
// to 1 and above (red), black where nothing was estimated.
Image heat_map(const Image& relative_error);

}  // namespace mvpl::preview
