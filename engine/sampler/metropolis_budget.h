#pragma once
// The Metropolis start pool by time budget (docs/results.md, "The reference's own noise and the
// 60 s target"). At these budgets each of the 1024 chains takes a few tens of steps, so the image
// is the bootstrap's start states, resampled ∝ I', and their small-step neighbourhoods: the pool
// is fixed when the run starts and its low-frequency error (blotches of the camera room's few
// start states) stays however long the run goes. Two-room at 60 s, seeds 1–2: 4× the bootstrap and
// the chains took the error against the truth from 3.6 and 4.3 · 10⁻³ to 2.4 and 2.2 · 10⁻³ (its
// low-frequency part, 8×8 blocks, from 2.3 and 3.2 to 0.85 and 0.79 · 10⁻³) for 4–5 s of a
// 60 s budget spent on the bootstrap instead of ≈1.3 s. Short budgets keep the defaults, where
// that time would be the whole render's. Only the pool's size changes, not the sampler: the
// estimate is the same unbiased one.
//
// The bootstrap grows faster than the chains, as (T / 15 s)^1.5 up to 8× (524288 paths at 60 s):
// with stratified starts (start_resampling.h) and at 60 s (--interleave 1, four seeds, against
// the mean of four references) 8× took the error against the truth from 1.09, 1.07, 1.51, 1.05
// to 1.05, 0.94, 0.87, 0.63 · 10⁻³ and the image mean's largest deviation from 3.3 % to 1.7 %, for
// ≈ 9.5 s of sampling instead of 4; 16× (1048576) gave 0.71, 0.97, 0.93, 0.74 for 11–16 s
// (docs/results.md, "Four references, stratified starts and the 60 s target").
#include "engine/sampler/sampler_factory.h"

namespace mvpl::sampler {

// Budgets up to this keep MetropolisOptions' chains and bootstrap; longer ones scale the chains by
// (budget / kPoolBudgetSeconds)², at most kMaxPoolScale (16384 chains at 60 s), and the bootstrap
// as below. At 60 s each of 4096 chains took ≈ 8 steps and the image mean's spread over seeds was
// the chains' own (their starts' resampling and steps: with every other seed fixed, a new chain
// seed moved seed 6 from 0.986 to 0.995, a new bootstrap, importance-point, direct-light,
// compensation or sub-pixel seed did not); 16384 chains of ≈ 2 steps took relMSE against the
// truth from 0.57 to 0.47 · 10⁻³ (mean of twelve seeds) and put every channel within 1 % on 11 of
// 12 seeds against 9 (docs/results.md, "Sixteen thousand chains at 60 s").
inline constexpr double kPoolBudgetSeconds = 15.0;
inline constexpr double kMaxPoolScale = 16.0;
// The bootstrap's scale: (budget / kPoolBudgetSeconds)^1.5, at most this.
inline constexpr double kMaxBootstrapScale = 8.0;

// Scales settings.chains and settings.bootstrap for a render of `seconds` (≤ 0: not a time
// budget, unchanged). A value the user chose (chains_given, bootstrap_given) stays as it is.
void scale_pool_for_budget(SamplerSettings& settings, double seconds, bool chains_given,
                           bool bootstrap_given);

}  // namespace mvpl::sampler
