#pragma once
// Where the Metropolis chains start (metropolis_stream.h): the bootstrap pool resampled ∝ I'.
//
// At interactive and minute budgets the chains take a few steps each (two-room, 60 s: 4096 chains,
// ≈ 4.5 steps each), so the image is close to the starts and their neighbourhoods, and independent
// picks leave each region of the scene with a Poisson-distributed number of starts: a wall region
// that expects 30 gets 30 ± 5.5, a blotch 18 % too bright or dark (docs/results.md, "Four
// references, stratified starts and the 60 s target"). Systematic resampling over the pool sorted
// along a space-filling curve of the states' VPL positions gives each region its expected count to
// within one: the starts are stratified in space. It stays unbiased: item i is picked count·w_i/Σw
// times in expectation whatever the order, and the picks are shuffled so that chain c's start is
// marginally ∝ w for every c, so that chains which run an extra step (a run's steps are rarely a
// multiple of the chains) weight no region more than another
// (tests/sampler/test_start_resampling.cpp).
#include <cstdint>
#include <span>
#include <vector>

#include "engine/core/math.h"
#include "engine/core/rng.h"
#include "engine/scene/bounds.h"

namespace mvpl::sampler {

// A 30-bit Morton code (10 bits an axis) of p in `bounds`; points outside are clamped to it.
uint32_t morton_key(const Vec3& p, const scene::Bounds& bounds);

// `count` indices into `weights` (≥ 0 and finite, with a positive sum): systematic resampling
// (one uniform offset, equal spacing) over the items in the order of `keys` (ties by index), then
// shuffled (Fisher–Yates). Item i appears floor or ceil of count·w_i/Σw times; a zero weight never.
std::vector<uint64_t> stratified_picks(std::span<const double> weights,
                                       std::span<const double> keys, uint64_t count, Rng& rng);

}  // namespace mvpl::sampler
