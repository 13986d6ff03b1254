#pragma once
// How long a light path may be: Mitsuba's max_depth, the most segments of the whole
// camera-to-light path (< 0: unlimited). One default for every estimator — the path tracer, the
// light tracer's VPLs, the oracle, the clamping compensation and the caustic tracer — so that they
// all stop at the same depth and their images add up to one estimate. 6 is what the Cornell box
// and two-room references were rendered with (docs/results.md, "Overview").

namespace mvpl::light {

inline constexpr int kDefaultMaxDepth = 6;
// Russian roulette from this many segments on, in every estimator that traces paths (Mitsuba's
// rrDepth default, as the references were rendered).
inline constexpr int kDefaultRrDepth = 5;

}  // namespace mvpl::light
