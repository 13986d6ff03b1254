#pragma once
// Clustering the columns of the reduced matrix (Hašan et al. 2007): C clusters whose
// representatives estimate the pool's sum with little error on the rows. A cluster K, shaded
// through one column j drawn with probability n_j / Σ_K n (n = ‖ρ‖), estimates Σ_K ρ with the
// error E‖X − Σ_K ρ‖² = (Σ_K n)² − ‖Σ_K ρ‖² = ½ Σ_{i,j ∈ K} n_i n_j ‖ρ̂_i − ρ̂_j‖² (ρ̂ = ρ/n): the
// paper's cluster cost, which both stages reduce, measured on the columns' sketches
// (reduced_matrix.h; directions ρ̂ from the sketch, norms exact).
//
// 1. Sampling clustering: C/2 centres drawn with replacement in proportion to
//    α_j = Σ_i n_i n_j ‖ρ̂_i − ρ̂_j‖² = n_j (2 Σ n − 2 ρ̂_j · Σ n ρ̂), which favours columns far from
//    the rest, and every column joined to the centre nearest in direction (nearest_centre.h: for
//    many centres, the nearest among those of a few groups).
// 2. Top-down splitting: first every cluster of more than kLargestCluster times the mean
//    cluster's columns halved at the median along a random line, then the cluster of largest
//    cost split along a random line at the point of least total cost, until C clusters (or every
//    cost is 0).
//
// The cost is the error on the rows. What no row sees grows with a cluster's size instead: its
// representative carries about the cluster's size in weight, and columns whose sketches are
// nearly parallel (VPLs that the rows barely see, such as the far room's in the two rooms) cost
// little and gather by the thousand, so one of them lit a wall beside the opening that no row
// sees at thousands of times a VPL's power. Bounding the size bounds that weight.
//
// Columns with norm 0 (no row sees their light) get clusters of their own, in proportion to
// their count, cut in pool order; their representatives are drawn by power
// (representatives.h), so that a VPL that lights only pixels no row sees still contributes in
// expectation. With C ≥ N every column is a cluster of its own.
#include <cstdint>
#include <span>
#include <vector>

#include "engine/manylights/reduced_matrix.h"

namespace mvpl::manylights {

// At most this many times the mean cluster's columns (N/C for N seen columns in C clusters) in a
// cluster. Measured (docs/results.md, "Clusters of bounded size"): with 8 the two rooms' relMSE at
// a fixed count fell 1.3–10× (seeds 1–4) and the Cornell box's moved by −5 to +4 %; 2 and 4
// gained the same on the two rooms and cost the Cornell box 4–10 % per pixel (the splits they
// force leave fewer for the cost).
inline constexpr double kLargestCluster = 8.0;

struct Cluster {
    std::vector<uint32_t> columns;
    bool seen = true;  // false: columns of norm 0, drawn by power
};

// Deterministic for the same sketches, count and seed.
std::vector<Cluster> cluster_columns(const ColumnSketches& sketches, uint32_t clusters,
                                     uint64_t seed);

// The summed cost above of the clusters of seen columns, from the norms and directions of their
// columns (tests, reports); the unseen clusters' cost is not on the rows.
double clusters_cost(const ColumnSketches& sketches, std::span<const Cluster> clusters);

}  // namespace mvpl::manylights
