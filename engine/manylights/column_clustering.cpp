#include "engine/manylights/column_clustering.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <queue>

#include "engine/core/parallel.h"
#include "engine/core/rng.h"
#include "engine/core/sampling.h"
#include "engine/manylights/nearest_centre.h"

namespace mvpl::manylights {
namespace {

// Unit directions of the sketches (a sketch of norm 0 keeps the zero vector: as far from every
// direction as any other).
std::vector<float> directions(const ColumnSketches& s) {
    std::vector<float> d = s.sketch;
    for (size_t j = 0; j < s.norms.size(); ++j) {
        float* v = &d[j * s.dims];
        double len2 = 0.0;
        for (uint32_t k = 0; k < s.dims; ++k)
            len2 += double(v[k]) * double(v[k]);
        const float inv = len2 > 0.0 ? float(1.0 / std::sqrt(len2)) : 0.0f;
        for (uint32_t k = 0; k < s.dims; ++k)
            v[k] *= inv;
    }
    return d;
}

// Σ n and Σ n ρ̂ of a set of columns; cost = (Σ n)² − ‖Σ n ρ̂‖².
struct Sums {
    double norm = 0.0;
    std::vector<double> vec;
    explicit Sums(uint32_t dims) : vec(dims, 0.0) {}
    void add(double n, const float* dir, double sign = 1.0) {
        norm += sign * n;
        for (size_t k = 0; k < vec.size(); ++k)
            vec[k] += sign * n * double(dir[k]);
    }
    double cost() const {
        double s2 = 0.0;
        for (double v : vec)
            s2 += v * v;
        return std::max(0.0, norm * norm - s2);
    }
};

// Sampling clustering of `columns` (norm > 0) into at most `count` clusters.
std::vector<std::vector<uint32_t>> sampling_clusters(const ColumnSketches& s,
                                                     const std::vector<float>& dir,
                                                     const std::vector<uint32_t>& columns,
                                                     uint32_t count, Rng& rng) {
    const uint32_t dims = s.dims;
    Sums all(dims);
    for (uint32_t j : columns)
        all.add(s.norms[j], &dir[size_t(j) * dims]);
    std::vector<double> cdf(columns.size());
    double total = 0.0;
    for (size_t i = 0; i < columns.size(); ++i) {
        const uint32_t j = columns[i];
        double proj = 0.0;
        for (uint32_t k = 0; k < dims; ++k)
            proj += double(dir[size_t(j) * dims + k]) * all.vec[k];
        total += std::max(0.0, double(s.norms[j]) * (2.0 * all.norm - 2.0 * proj));
        cdf[i] = total;
    }
    if (!(total > 0.0)) {  // every column in one direction: draw by norm
        total = 0.0;
        for (size_t i = 0; i < columns.size(); ++i)
            cdf[i] = total += s.norms[columns[i]];
    }
    std::vector<uint32_t> centres;
    for (uint32_t c = 0; c < count; ++c) {
        const double u = double(rng.next_float()) * total;
        const size_t i = size_t(std::upper_bound(cdf.begin(), cdf.end(), u) - cdf.begin());
        centres.push_back(columns[std::min(i, columns.size() - 1)]);
    }
    std::sort(centres.begin(), centres.end());
    centres.erase(std::unique(centres.begin(), centres.end()), centres.end());
    const std::vector<uint32_t> nearest = nearest_centres(dir, dims, columns, centres);
    std::vector<std::vector<uint32_t>> clusters(centres.size());
    for (size_t i = 0; i < columns.size(); ++i)
        clusters[nearest[i]].push_back(columns[i]);
    std::erase_if(clusters, [](const auto& c) { return c.empty(); });
    return clusters;
}

}  // namespace

namespace {

double cost_of(const ColumnSketches& s, const std::vector<float>& dir,
               const std::vector<uint32_t>& columns) {
    Sums sums(s.dims);
    for (uint32_t j : columns)
        sums.add(s.norms[j], &dir[size_t(j) * s.dims]);
    return sums.cost();
}

// The point of least total cost along `order` (columns sorted along a line): the first `at`
// columns and the rest; 0 when no split lowers the cost.
size_t least_cost_point(const ColumnSketches& s, const std::vector<float>& dir,
                        const std::vector<std::pair<double, uint32_t>>& order) {
    const uint32_t dims = s.dims;
    Sums whole(dims), left(dims);
    for (const auto& o : order)
        whole.add(s.norms[o.second], &dir[size_t(o.second) * dims]);
    double best = whole.cost();
    size_t at = 0;
    for (size_t m = 1; m < order.size(); ++m) {
        const uint32_t j = order[m - 1].second;
        left.add(s.norms[j], &dir[size_t(j) * dims]);
        whole.add(s.norms[j], &dir[size_t(j) * dims], -1.0);
        const double c = left.cost() + whole.cost();
        if (c < best) {
            best = c;
            at = m;
        }
    }
    return at;
}

// Splits `columns` along a random line, at the point of least total cost or, with `halve`, at
// the median; false when no split lowers the cost.
bool split(const ColumnSketches& s, const std::vector<float>& dir, std::vector<uint32_t>& columns,
           std::vector<uint32_t>& right, Rng& rng, bool halve) {
    const uint32_t dims = s.dims;
    std::vector<float> line(dims);
    for (float& v : line)
        v = float(std::sqrt(-2.0 * std::log(1.0 - double(rng.next_float()))) *
                  std::cos(2.0 * kPi * double(rng.next_float())));
    std::vector<std::pair<double, uint32_t>> order;
    order.reserve(columns.size());
    for (uint32_t j : columns)
        order.emplace_back(direction_dot(&dir[size_t(j) * dims], line.data(), dims), j);
    std::sort(order.begin(), order.end());
    const size_t at = halve ? order.size() / 2 : least_cost_point(s, dir, order);
    if (at == 0) return false;
    columns.clear();
    right.clear();
    for (size_t m = 0; m < order.size(); ++m)
        (m < at ? columns : right).push_back(order[m].second);
    return true;
}

// Top-down splitting of `clusters` until `count` or none can be split; clusters of more than
// `cap` columns first, halved.
void split_clusters(const ColumnSketches& s, const std::vector<float>& dir,
                    std::vector<std::vector<uint32_t>>& clusters, uint32_t count, size_t cap,
                    Rng& rng) {
    struct Entry {
        bool over;
        double cost;
        size_t k;
    };
    // The oversized first, then the largest cost, then the lowest index.
    auto later = [](const Entry& a, const Entry& b) {
        if (a.over != b.over) return b.over;
        return a.cost != b.cost ? a.cost < b.cost : a.k > b.k;
    };
    std::priority_queue<Entry, std::vector<Entry>, decltype(later)> queue(later);
    auto push = [&](size_t k) {
        queue.push(Entry{clusters[k].size() > cap, cost_of(s, dir, clusters[k]), k});
    };
    for (size_t k = 0; k < clusters.size(); ++k)
        push(k);
    while (clusters.size() < count && !queue.empty()) {
        const Entry e = queue.top();
        queue.pop();
        if (!e.over && (!(e.cost > 0.0) || clusters[e.k].size() < 2)) continue;
        std::vector<uint32_t> right;
        if (!split(s, dir, clusters[e.k], right, rng, e.over)) continue;
        clusters.push_back(std::move(right));
        push(e.k);
        push(clusters.size() - 1);
    }
}

}  // namespace

double clusters_cost(const ColumnSketches& s, std::span<const Cluster> clusters) {
    const std::vector<float> dir = directions(s);
    double total = 0.0;
    for (const Cluster& k : clusters)
        total += k.seen ? cost_of(s, dir, k.columns) : 0.0;
    return total;
}

std::vector<Cluster> cluster_columns(const ColumnSketches& s, uint32_t clusters, uint64_t seed) {
    clusters = std::max(clusters, 1u);
    const size_t n = s.norms.size();
    std::vector<Cluster> out;
    if (clusters >= n) {
        for (uint32_t j = 0; j < n; ++j)
            out.push_back(Cluster{{j}, s.norms[j] > 0.0f});
        return out;
    }
    std::vector<uint32_t> seen, unseen;
    for (uint32_t j = 0; j < n; ++j)
        (s.norms[j] > 0.0f ? seen : unseen).push_back(j);
    // The unseen columns' share of the clusters: their share of the columns, at least one.
    uint32_t zero = 0;
    if (!unseen.empty()) {
        zero = std::clamp<uint32_t>(
            uint32_t(std::lround(double(clusters) * double(unseen.size()) / double(n))), 1,
            seen.empty() ? clusters : std::max(clusters, 2u) - 1);
    }
    // At least one cluster for the seen columns, even if C = 1.
    const uint32_t count = seen.empty() ? 0 : std::max(clusters - std::min(zero, clusters), 1u);
    Rng rng(mix_bits(seed ^ 0x636c7573746572ULL), 0);
    std::vector<std::vector<uint32_t>> parts;
    if (count >= seen.size()) {
        for (uint32_t j : seen)
            parts.push_back({j});
    } else if (count > 0) {
        const std::vector<float> dir = directions(s);
        parts = sampling_clusters(s, dir, seen, std::max(count / 2, 1u), rng);
        const auto cap = size_t(std::ceil(kLargestCluster * double(seen.size()) / double(count)));
        split_clusters(s, dir, parts, count, cap, rng);
    }
    for (auto& p : parts)
        out.push_back(Cluster{std::move(p), true});
    // Unseen columns in pool order, cut into `zero` runs of (nearly) equal length.
    for (uint32_t z = 0; z < zero; ++z) {
        Cluster c{{}, false};
        for (size_t i = unseen.size() * z / zero; i < unseen.size() * (z + 1) / zero; ++i)
            c.columns.push_back(unseen[i]);
        if (!c.columns.empty()) out.push_back(std::move(c));
    }
    return out;
}

}  // namespace mvpl::manylights
