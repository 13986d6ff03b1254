#include "engine/sampler/start_resampling.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace mvpl::sampler {

namespace {

// Spreads the low 10 bits of v to every third bit.
uint32_t spread_bits(uint32_t v) {
    v &= 0x3ffu;
    v = (v | (v << 16)) & 0x030000ffu;
    v = (v | (v << 8)) & 0x0300f00fu;
    v = (v | (v << 4)) & 0x030c30c3u;
    v = (v | (v << 2)) & 0x09249249u;
    return v;
}

uint32_t cell(float x, float lo, float hi) {
    const float extent = hi - lo;
    if (!(extent > 0.0f)) return 0;
    const float t = std::clamp((x - lo) / extent, 0.0f, 1.0f);
    return std::min(uint32_t(t * 1024.0f), 1023u);
}

}  // namespace

uint32_t morton_key(const Vec3& p, const scene::Bounds& bounds) {
    if (bounds.empty()) return 0;
    return spread_bits(cell(p.x, bounds.lo.x, bounds.hi.x)) |
           (spread_bits(cell(p.y, bounds.lo.y, bounds.hi.y)) << 1) |
           (spread_bits(cell(p.z, bounds.lo.z, bounds.hi.z)) << 2);
}

std::vector<uint64_t> stratified_picks(std::span<const double> weights,
                                       std::span<const double> keys, uint64_t count, Rng& rng) {
    const size_t n = weights.size();
    std::vector<uint64_t> order(n);
    std::iota(order.begin(), order.end(), uint64_t(0));
    std::stable_sort(order.begin(), order.end(),
                     [&](uint64_t a, uint64_t b) { return keys[a] < keys[b]; });
    double total = 0.0;
    for (double w : weights)
        total += w;
    std::vector<uint64_t> picks;
    picks.reserve(count);
    if (n == 0 || count == 0 || !(total > 0.0)) return picks;
    // Pick k is the item whose interval of the running sum holds (k + u)·Σw / count.
    const double spacing = total / double(count);
    double x = double(rng.next_float()) * spacing;
    double running = 0.0;
    size_t j = 0;
    for (uint64_t k = 0; k < count; ++k, x += spacing) {
        while (j + 1 < n && !(running + weights[order[j]] > x)) {
            running += weights[order[j]];
            ++j;
        }
        // Rounding at the very end of the sum: the last item with a weight.
        size_t at = j;
        while (at > 0 && !(weights[order[at]] > 0.0))
            --at;
        picks.push_back(order[at]);
    }
    for (uint64_t k = count - 1; k > 0; --k) {
        const uint64_t other =
            std::min<uint64_t>(uint64_t(double(rng.next_float()) * double(k + 1)), k);
        std::swap(picks[k], picks[other]);
    }
    return picks;
}

}  // namespace mvpl::sampler
