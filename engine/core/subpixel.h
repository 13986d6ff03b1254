#pragma once
// Sub-pixel sample positions for anti-aliasing (docs/design.md, "GPU passes"): the GPU renderer
// draws its G-buffer at one position per group of VPLs, and the CPU oracle shades the same VPLs at
// the same positions, so that both estimate the box-filtered pixel (as Mitsuba's reference does).
//
// The sequence: the pixel centre first (so that an image of one batch is the pixel-centre image),
// then antithetic pairs c ± (r_j − c) about the centre c = (½, ½), r_j the R2 sequence (Roberts
// 2018, "The unreasonable effectiveness of quasirandom sequences": the Kronecker lattice
// ½ + j·(1/g, 1/g²) mod 1, g the plastic number). The pairs keep the mean position of every
// odd-length prefix exactly at the centre, which matters at low batch counts: a smooth image
// gradient sampled at positions whose mean is off by δ is off by δ · gradient. Unpaired base-2
// nets such as the (0,2)-sequence (Sobol, Kollig & Keller 2002) are left-aligned in their
// strata, δ = −1/(2N) per axis for N = 2^m positions; at 8 positions that darkened 4×4 blocks of
// an area-lit plane by 5 % against the path tracer, where pixel centres were 2 % off
// (tests/sampler/test_direct_vpl.cpp, AreaLightConvergesToThePathTracer). Against the
// (0,2)-sequence on 40 random half-planes through a pixel, the RMS error of the covered fraction
// was 0.099 / 0.026 / 0.0094 / 0.0062 at 8 / 32 / 128 / 256 positions ((0,2): 0.093 / 0.028 /
// 0.0087 / 0.0051).
//
// A seed rotates the lattice (Cranley & Patterson 1976: r_j + u mod 1, u from the seed) and moves
// the first position from the centre to ½ + u mod 1; the pairs stay antithetic about the centre.
// Every position of a rotated sequence is then uniform over the pixel across seeds, so the
// quadrature over the pixel is unbiased and its error varies with the seed as the light's does:
// the difference of two seeds' images measures all of the error, not only the part the VPLs make
// (tests/cli/test_sample_models.cpp). With the centre kept for every seed, a feature smaller than
// a pixel at its centre (a highlight seen through a specular chain) weighed 1/N of N positions in
// every render: 16.9× the path tracer in one pixel of assets/glossy at 32 positions, at both
// seeds measured (docs/results.md). The price: an odd prefix's mean position is off the centre by
// (u − ½)/N, zero in the mean over seeds. Rotation 0 is the plain sequence, centre first.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "engine/core/math.h"
#include "engine/core/rng.h"

namespace mvpl {

// The sample position of `index` inside the pixel, in [0, 1)²; for index 0 the centre (0.5, 0.5)
// shifted by `rotation` (mod 1). `rotation` in [0, 1)² shifts the lattice of the pairs too
// (subpixel_rotation).
inline Vec2 subpixel_position(uint64_t index, Vec2 rotation = Vec2(0.0f)) {
    constexpr float kBelowOne = 0x1.fffffep-1f;  // the largest float below 1
    if (index == 0) {
        const auto wrap = [](float v) { return v >= 0.5f ? v - 0.5f : v + 0.5f; };
        return Vec2(std::min(wrap(rotation.x), kBelowOne), std::min(wrap(rotation.y), kBelowOne));
    }
    constexpr double kPlastic = 1.32471795724474602596;  // the real root of x³ = x + 1
    // In double: j·a keeps ~1e-16·j absolute error, far below a float's resolution in a pixel.
    const double j = double((index + 1) / 2);
    double x = 0.5 + double(rotation.x) + j / kPlastic;
    double y = 0.5 + double(rotation.y) + j / (kPlastic * kPlastic);
    x -= std::floor(x);
    y -= std::floor(y);
    if (index % 2 == 0) {  // the second of the pair: reflected about the centre
        x = 1.0 - x;
        y = 1.0 - y;
    }
    return Vec2(std::min(float(x), kBelowOne), std::min(float(y), kBelowOne));
}

// The rotation for a seed: two well-spread values in [0, 1) (the top 24 bits of two mixed words).
inline Vec2 subpixel_rotation(uint64_t seed) {
    const uint64_t a = mix_bits(seed ^ 0x9e3779b97f4a7c15ULL);
    const uint64_t b = mix_bits(a);
    return Vec2(float(a >> 40) * 0x1p-24f, float(b >> 40) * 0x1p-24f);
}

// Which VPLs share a sub-pixel position: VPL i (counted from the start of an image) is shaded at
// position i / vpls_per_position; jitter false puts every VPL at the pixel centre.
struct SubpixelSchedule {
    bool jitter = true;
    uint64_t vpls_per_position = 32;
    Vec2 rotation{0.0f};  // subpixel_rotation(seed), or 0

    uint64_t position_of(uint64_t vpl) const {
        return jitter && vpls_per_position > 0 ? vpl / vpls_per_position : 0;
    }
    // The index of position p's first VPL.
    uint64_t first_of(uint64_t p) const { return jitter ? p * vpls_per_position : 0; }
    // The positions drawn once `vpls` VPLs were shaded: at least one (the image's first), which
    // the emitted radiance seen directly is averaged over.
    uint64_t positions_after(uint64_t vpls) const {
        return vpls == 0 ? 1 : position_of(vpls - 1) + 1;
    }
    Vec2 position(uint64_t index) const {
        return jitter ? subpixel_position(index, rotation) : Vec2(0.5f);
    }
};

}  // namespace mvpl
