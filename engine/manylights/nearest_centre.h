#pragma once
// The sampling clustering's assignment step (column_clustering.h): each column joined to the
// centre nearest in direction, the centre whose unit sketch direction has the largest dot product
// with the column's (the lowest of equals; a centre is nearest to itself). Directions are rows of
// `dir`, `dims` floats each, unit or zero (a sketch of norm 0); `centres` ascending.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace mvpl::manylights {

// Σ a_k b_k in double, term by term in k's order: the searches' sums, bit for bit (a product of
// two floats is exact in double, so contracting it into an FMA cannot change the sum either).
double direction_dot(const float* a, const float* b, uint32_t dims);

// Every column against every centre: columns · centres · dims products.
std::vector<uint32_t> nearest_centres_exhaustive(const std::vector<float>& dir, uint32_t dims,
                                                 const std::vector<uint32_t>& columns,
                                                 const std::vector<uint32_t>& centres);

// The nearest centre among the members of a few groups: of M centres, G = ⌈√M⌉ pivots, centre
// ⌊g M / G⌋ for g < G (the centres are in pool order, so a spread sample of them), each centre in
// the group of its nearest pivot, and a column compared with the pivots and then with the members
// of the groups of its kProbedGroups nearest pivots: about (1 + kProbedGroups) √M dot products a
// column instead of M. (The sampling clustering draws M = C/2 centres, and with the default
// C = N/16 the exhaustive search grows as N².) A column whose nearest centre is in a group not
// probed joins the nearest of those probed: the clusters only steer which representatives are
// drawn, so the estimate stays unbiased and the clusters cost a little more (docs/results.md,
// "Clustering large pools": +1.3–2 % in the clusters' summed cost at N = 65 536, C = 4 096).
std::vector<uint32_t> nearest_centres(const std::vector<float>& dir, uint32_t dims,
                                      const std::vector<uint32_t>& columns,
                                      const std::vector<uint32_t>& centres);

// Up to this many centres (C = 2 048: pools up to 32 768 at the default C) nearest_centres() is
// the exhaustive search, about as fast there.
constexpr size_t kExhaustiveCentres = 1024;
// Eight: at N = 65 536, C = 4 096 the clusters' summed cost was 1.3–2 % above the exhaustive
// search's (four: 2.8–3 %), the clustering 6× faster (four: 9×).
constexpr size_t kProbedGroups = 8;

}  // namespace mvpl::manylights
