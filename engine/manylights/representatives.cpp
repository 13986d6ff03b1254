#include "engine/manylights/representatives.h"

#include <algorithm>

namespace mvpl::manylights {
namespace {

double power_measure(const light::Vpl& v) {
    return double(std::max(v.power.r, 0.0f)) + double(std::max(v.power.g, 0.0f)) +
           double(std::max(v.power.b, 0.0f));
}

// Σ n and Σ φ over a cluster.
struct Totals {
    double norm = 0.0;
    double power = 0.0;
};
Totals totals(const Cluster& cluster, std::span<const float> norms,
              std::span<const light::Vpl> vpls) {
    Totals t;
    for (uint32_t j : cluster.columns) {
        t.norm += double(norms[j]);
        t.power += power_measure(vpls[j]);
    }
    return t;
}

double probability(const Cluster& cluster, uint32_t j, const Totals& t,
                   std::span<const float> norms, std::span<const light::Vpl> vpls,
                   float defensive_share) {
    if (cluster.columns.size() == 1) return 1.0;
    const double by_power =
        t.power > 0.0 ? power_measure(vpls[j]) / t.power : 1.0 / double(cluster.columns.size());
    if (!cluster.seen || !(t.norm > 0.0)) return by_power;
    const double e = std::clamp(double(defensive_share), 0.0, 1.0);
    return (1.0 - e) * double(norms[j]) / t.norm + e * by_power;
}

}  // namespace

double selection_probability(const Cluster& cluster, size_t i, std::span<const float> norms,
                             std::span<const light::Vpl> vpls, float defensive_share) {
    return probability(cluster, cluster.columns[i], totals(cluster, norms, vpls), norms, vpls,
                       defensive_share);
}

void append_representatives(const std::vector<Cluster>& clusters, std::span<const float> norms,
                            std::span<const light::Vpl> vpls, float defensive_share, Rng& rng,
                            std::vector<light::Vpl>& out) {
    for (const Cluster& cluster : clusters) {
        if (cluster.columns.empty()) continue;
        if (cluster.columns.size() == 1) {
            out.push_back(vpls[cluster.columns[0]]);
            continue;
        }
        const Totals t = totals(cluster, norms, vpls);
        // Inverse CDF; the last column with p > 0 where rounding leaves u past the sum.
        const double u = double(rng.next_u32()) * 0x1p-32;
        double sum = 0.0, p = 0.0;
        uint32_t pick = cluster.columns.back();
        for (uint32_t j : cluster.columns) {
            const double pj = probability(cluster, j, t, norms, vpls, defensive_share);
            if (pj > 0.0) {
                pick = j;
                p = pj;
            }
            sum += pj;
            if (u < sum && pj > 0.0) break;
        }
        if (!(p > 0.0)) continue;  // no column with power or norm: nothing to shade
        light::Vpl v = vpls[pick];
        v.power *= float(1.0 / p);
        out.push_back(v);
    }
}

}  // namespace mvpl::manylights
