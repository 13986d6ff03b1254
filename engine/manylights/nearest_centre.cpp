#include "engine/manylights/nearest_centre.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "engine/core/parallel.h"

namespace mvpl::manylights {
namespace {

// Two doubles a register (SSE2, the x86-64 baseline), by the GCC and Clang vector extension:
// the compilers leave the scalar loop of direction_dot() unvectorised.
using Double2 = double __attribute__((vector_size(16)));

// A set of centres' directions held transposed, per dimension, so that a column's D-term dot
// products with a block of them are summed side by side, each in direction_dot()'s order: the
// same sums, bit for bit, in a third of the time (docs/results.md, "Row-column sampling").
class TransposedCentres {
public:
    static constexpr size_t kBlock = 8;  // centres summed at once: their sums stay in registers

    // `ids`: indices into `centres`, whose directions are rows of `dir`.
    TransposedCentres(const std::vector<float>& dir, uint32_t dims,
                      const std::vector<uint32_t>& centres, std::vector<uint32_t> ids)
        : m_dims(dims),
          m_ids(std::move(ids)),
          m_padded((m_ids.size() + kBlock - 1) / kBlock * kBlock),
          m_across(size_t(dims) * m_padded, 0.0) {
        for (size_t c = 0; c < m_ids.size(); ++c)
            for (uint32_t k = 0; k < dims; ++k)
                m_across[k * m_padded + c] = double(dir[size_t(centres[m_ids[c]]) * dims + k]);
    }

    // each(id, x · centre) for every centre of the set, in the set's order.
    template <class Each>
    void dots(const float* x, Each&& each) const {
        for (size_t b = 0; b < m_padded; b += kBlock) {
            Double2 sum[kBlock / 2] = {};
            for (uint32_t k = 0; k < m_dims; ++k) {
                const Double2 xk = {double(x[k]), double(x[k])};
                const double* a = &m_across[k * m_padded + b];
                for (size_t v = 0; v < kBlock / 2; ++v) {
                    Double2 pair;
                    std::memcpy(&pair, a + 2 * v, sizeof pair);
                    sum[v] += xk * pair;
                }
            }
            for (size_t u = 0; u < kBlock && b + u < m_ids.size(); ++u)
                each(m_ids[b + u], sum[u / 2][u % 2]);
        }
    }

    size_t size() const { return m_ids.size(); }

private:
    uint32_t m_dims;
    std::vector<uint32_t> m_ids;
    size_t m_padded;
    std::vector<double> m_across;  // dimension k at [k · m_padded, …)
};

std::vector<uint32_t> all_ids(size_t count) {
    std::vector<uint32_t> ids(count);
    for (size_t c = 0; c < count; ++c)
        ids[c] = uint32_t(c);
    return ids;
}

// A centre is nearest to itself (its cosine counts as 2, above any other's).
uint32_t itself_or(uint32_t column, const std::vector<uint32_t>& centres, uint32_t pick) {
    const auto self = std::lower_bound(centres.begin(), centres.end(), column);
    return self != centres.end() && *self == column ? uint32_t(self - centres.begin()) : pick;
}

// Centres grouped around pivots: every (M / G)-th of the M centres (they are in pool order, so
// the pivots are a spread sample of them), each centre in the group of its nearest pivot.
struct CentreGroups {
    TransposedCentres pivots;
    std::vector<TransposedCentres> members;
};

CentreGroups group_centres(const std::vector<float>& dir, uint32_t dims,
                           const std::vector<uint32_t>& centres) {
    const size_t count = centres.size();
    const size_t groups = size_t(std::ceil(std::sqrt(double(count))));
    std::vector<uint32_t> pivot_ids(groups), pivot_columns(groups);
    for (size_t g = 0; g < groups; ++g) {
        pivot_ids[g] = uint32_t(g * count / groups);
        pivot_columns[g] = centres[pivot_ids[g]];
    }
    const std::vector<uint32_t> nearest =
        nearest_centres_exhaustive(dir, dims, centres, pivot_columns);
    std::vector<std::vector<uint32_t>> ids(groups);
    for (uint32_t c = 0; c < count; ++c)
        ids[nearest[c]].push_back(c);
    CentreGroups out{TransposedCentres(dir, dims, centres, pivot_ids), {}};
    for (auto& g : ids)
        out.members.emplace_back(dir, dims, centres, std::move(g));
    return out;
}

}  // namespace

double direction_dot(const float* a, const float* b, uint32_t dims) {
    double s = 0.0;
    for (uint32_t k = 0; k < dims; ++k)
        s += double(a[k]) * double(b[k]);
    return s;
}

std::vector<uint32_t> nearest_centres_exhaustive(const std::vector<float>& dir, uint32_t dims,
                                                 const std::vector<uint32_t>& columns,
                                                 const std::vector<uint32_t>& centres) {
    const TransposedCentres all(dir, dims, centres, all_ids(centres.size()));
    std::vector<uint32_t> nearest(columns.size());
    parallel_for(int64_t(columns.size()), 256, [&](int64_t begin, int64_t end) {
        for (int64_t i = begin; i < end; ++i) {
            const uint32_t column = columns[size_t(i)];
            double best = -2.0;
            uint32_t pick = 0;
            all.dots(&dir[size_t(column) * dims], [&](uint32_t id, double d) {
                if (d > best) {
                    best = d;
                    pick = id;
                }
            });
            nearest[size_t(i)] = itself_or(column, centres, pick);
        }
    });
    return nearest;
}

std::vector<uint32_t> nearest_centres(const std::vector<float>& dir, uint32_t dims,
                                      const std::vector<uint32_t>& columns,
                                      const std::vector<uint32_t>& centres) {
    if (centres.size() <= kExhaustiveCentres)
        return nearest_centres_exhaustive(dir, dims, columns, centres);
    const CentreGroups groups = group_centres(dir, dims, centres);
    const size_t probes = std::min(kProbedGroups, groups.members.size());
    std::vector<uint32_t> nearest(columns.size());
    parallel_for(int64_t(columns.size()), 256, [&](int64_t begin, int64_t end) {
        std::vector<std::pair<double, uint32_t>> near;  // −(x · pivot), group
        near.reserve(groups.pivots.size());
        for (int64_t i = begin; i < end; ++i) {
            const uint32_t column = columns[size_t(i)];
            const float* x = &dir[size_t(column) * dims];
            near.clear();
            uint32_t g = 0;
            groups.pivots.dots(x, [&](uint32_t, double d) { near.emplace_back(-d, g++); });
            std::partial_sort(near.begin(), near.begin() + ptrdiff_t(probes), near.end());
            // The largest dot product, the lowest centre among equals (the exhaustive rule).
            double best = -2.0;
            uint32_t pick = 0;
            for (size_t q = 0; q < probes; ++q)
                groups.members[near[q].second].dots(x, [&](uint32_t id, double d) {
                    if (d > best || (d == best && id < pick)) {
                        best = d;
                        pick = id;
                    }
                });
            nearest[size_t(i)] = itself_or(column, centres, pick);
        }
    });
    return nearest;
}

}  // namespace mvpl::manylights
