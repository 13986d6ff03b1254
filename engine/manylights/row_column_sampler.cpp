#include "engine/manylights/row_column_sampler.h"

#include <algorithm>

#include "engine/core/rng.h"
#include "engine/core/timer.h"
#include "engine/manylights/column_clustering.h"
#include "engine/manylights/reduced_matrix.h"
#include "engine/manylights/representatives.h"

namespace mvpl::manylights {

RowColumnSampler::RowColumnSampler(const RowColumnContext& context, const RowColumnOptions& options)
    : m_context(context), m_options(options) {
    m_context.rows.rows = int(options.rows);
    const float diagonal = context.scene->bounds().diagonal();
    const float d_min = context.clamp * diagonal;
    const float radius = context.vsl_radius * diagonal;
    m_d_min2 = d_min * d_min;
    m_vsl_r2 = radius * radius;
}

std::vector<light::Vpl> RowColumnSampler::representatives(std::span<const light::Vpl> pool,
                                                          uint64_t pool_index, uint32_t clusters) {
    std::vector<light::Vpl> out;
    if (clusters >= pool.size()) {  // every VPL its own cluster: the pool itself
        out.assign(pool.begin(), pool.end());
        return out;
    }
    Timer matrix;
    const std::vector<Row> rows = make_rows(*m_context.scene, *m_context.accel, *m_context.camera,
                                            m_context.rows, m_context.seed, pool_index);
    const MatrixContext mc{m_context.accel, rows, m_d_min2, m_vsl_r2};
    const uint64_t pool_seed = mix_bits(m_context.seed ^ mix_bits(pool_index + 0x706f6f6cULL));
    const ColumnSketches sketches =
        m_context.columns ? m_context.columns->sketch(mc, pool, m_options.sketch_dims, pool_seed)
                          : sketch_columns(mc, pool, m_options.sketch_dims, pool_seed);
    m_stats.matrix_seconds += matrix.seconds();
    m_stats.rows += rows.size();
    Timer clustering;
    const std::vector<Cluster> parts = cluster_columns(sketches, clusters, pool_seed);
    Rng rng(pool_seed, 1);
    append_representatives(parts, sketches.norms, pool, m_options.defensive_share, rng, out);
    m_stats.cluster_seconds += clustering.seconds();
    return out;
}

uint64_t RowColumnSampler::pools_of(size_t count) const {
    const size_t n = std::max<size_t>(m_options.pool, 1);
    return (count + n - 1) / n;
}

void RowColumnSampler::reduce(std::vector<light::Vpl>& vpls, uint64_t first_pool) {
    const size_t n = std::max<size_t>(m_options.pool, 1);
    std::vector<light::Vpl> out;
    for (size_t begin = 0, pool = 0; begin < vpls.size(); begin += n, ++pool) {
        const size_t count = std::min(n, vpls.size() - begin);
        // A shorter pool keeps the full pool's ratio of clusters to VPLs (at least one).
        const uint32_t clusters = uint32_t(
            std::max<uint64_t>(1, (uint64_t(m_options.clusters_per_pool()) * count + n - 1) / n));
        std::vector<light::Vpl> reps = representatives(
            std::span<const light::Vpl>(vpls).subspan(begin, count), first_pool + pool, clusters);
        out.insert(out.end(), reps.begin(), reps.end());
        ++m_stats.pools;
        m_stats.columns += count;
    }
    m_stats.representatives += out.size();
    vpls = std::move(out);
}

}  // namespace mvpl::manylights
