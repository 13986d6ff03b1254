#pragma once
// One representative per cluster (Hašan et al. 2007): column j of cluster K drawn with
// probability p_j and shaded with its power divided by p_j, so that the representative's
// expectation is the cluster's sum, on every pixel and not only on the rows. A VPL's
// contribution is linear in its power — the clamp bounds the geometric term, max(d², d_min²),
// not the contribution (vpl.h) — so scaling the power by 1/p_j scales the shaded contribution,
// clamped or not, by exactly that.
//
// Seen clusters: p_j = (1 − ε) n_j / Σ_K n + ε φ_j / Σ_K φ (n the reduced column norm, φ the
// power's r + g + b, ε the defensive share), so p_j > 0 for every VPL with power. Unseen clusters
// (norm 0 on every row): p_j = φ_j / Σ_K φ. A cluster of one column: p = 1, the VPL unchanged.
#include <cstdint>
#include <span>
#include <vector>

#include "engine/core/rng.h"
#include "engine/light/vpl.h"
#include "engine/manylights/column_clustering.h"

namespace mvpl::manylights {

// The probability of the cluster's i-th column (p_j above).
double selection_probability(const Cluster& cluster, size_t i, std::span<const float> norms,
                             std::span<const light::Vpl> vpls, float defensive_share);

// Appends each cluster's representative, its power divided by its probability, to `out`.
void append_representatives(const std::vector<Cluster>& clusters, std::span<const float> norms,
                            std::span<const light::Vpl> vpls, float defensive_share, Rng& rng,
                            std::vector<light::Vpl>& out);

}  // namespace mvpl::manylights
