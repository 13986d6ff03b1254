#include "engine/render/ism_points.h"

#include <algorithm>
#include <cmath>

#include "engine/core/rng.h"
#include "engine/core/sampling.h"
#include "engine/render/host_vec3.h"

namespace mvpl::render {

std::vector<IsmPoint> sample_ism_points(const ShadowClusters& casters, uint32_t count,
                                        uint64_t seed) {
    const std::vector<Vec3>& p = casters.positions();
    // The full triangles only (each group's level 0), in cluster order.
    CasterRanges ranges;
    casters.level_ranges(Vec3(0.0f), LodChoice{}, ranges);
    std::vector<uint32_t> idx;
    for (const std::vector<gpu::IndexRange>& kind : ranges.by_kind) {
        for (const gpu::IndexRange& r : kind)
            idx.insert(idx.end(), casters.indices().begin() + r.first_index,
                       casters.indices().begin() + r.first_index + r.index_count);
    }
    const size_t triangles = idx.size() / 3;
    // The running sum of the areas, in double: a million small triangles would round away in
    // float.
    std::vector<double> cdf(triangles + 1, 0.0);
    for (size_t t = 0; t < triangles; ++t) {
        const Vec3 e1 = p[idx[3 * t + 1]] - p[idx[3 * t]];
        const Vec3 e2 = p[idx[3 * t + 2]] - p[idx[3 * t]];
        cdf[t + 1] = cdf[t] + 0.5 * double(glm::length(glm::cross(e1, e2)));
    }
    std::vector<IsmPoint> points;
    if (triangles == 0 || !(cdf.back() > 0.0)) return points;
    points.reserve(count);
    Rng rng(seed, 0x15a7);
    // Discs of twice the radius that gives each point its share of the area: random discs of
    // total area 4 × the surface's leave e^−4 ≈ 2 % of it uncovered (at 1×, e^−1 = 37 %: the
    // points behind showed through, two-room scene).
    const float radius = 2.0f * float(std::sqrt(cdf.back() / (kPi * double(count))));
    for (uint32_t i = 0; i < count; ++i) {
        const double target = (double(i) + double(rng.next_float())) / double(count) * cdf.back();
        size_t t = size_t(std::upper_bound(cdf.begin() + 1, cdf.end(), target) - cdf.begin()) - 1;
        t = std::min(t, triangles - 1);
        const Vec3 a = p[idx[3 * t]];
        const Vec3 b = p[idx[3 * t + 1]];
        const Vec3 c = p[idx[3 * t + 2]];
        const Vec2 bc = sample_uniform_triangle(Vec2(rng.next_float(), rng.next_float()));
        const Vec3 x = (1.0f - bc.x - bc.y) * a + bc.x * b + bc.y * c;
        const Vec3 cross = glm::cross(b - a, c - a);
        const float len = glm::length(cross);
        const Vec3 n = len > 0.0f ? cross / len : Vec3(0.0f, 0.0f, 1.0f);
        IsmPoint q{};
        store(q.position, x);
        store(q.normal, n);
        q.radius = radius;
        points.push_back(q);
    }
    return points;
}

}  // namespace mvpl::render
