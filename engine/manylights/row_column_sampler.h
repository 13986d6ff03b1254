#pragma once
// Matrix row-column sampling (Hašan, Pellacini, Bala 2007) as a transform of the VPL stream:
// each pool of N VPLs is replaced by C weighted representatives whose image, in expectation over
// the representatives' draw, is the pool's. Per pool: R rows (row_set.h), the R × N reduced
// matrix's column norms and sketches (reduced_matrix.h; Embree shadow rays on the CPU), the
// clustering (column_clustering.h) and one representative per cluster (representatives.h).
// The VplSet's scale is untouched, so the estimate is the stream's, unbiased, with C VPLs
// shaded per pool instead of N.
#include <cstdint>
#include <span>
#include <vector>

#include "engine/light/vpl.h"
#include "engine/manylights/reduced_matrix.h"
#include "engine/manylights/row_column_options.h"
#include "engine/manylights/row_set.h"
#include "engine/scene/scene.h"
#include "engine/trace/accel.h"

namespace mvpl::manylights {

// What the rows and the matrix take from the estimate.
struct RowColumnContext {
    const scene::Scene* scene = nullptr;
    const trace::Accel* accel = nullptr;
    const scene::Camera* camera = nullptr;
    RowSetOptions rows;       // image size and chains; rows.rows is set from the options
    float clamp = 0.0f;       // d_min / scene diagonal, the renderer's
    float vsl_radius = 0.0f;  // sphere radius / scene diagonal, the renderer's
    uint64_t seed = 0;
    // Evaluates the pools' columns; null: sketch_columns on the CPU.
    ColumnEvaluator* columns = nullptr;
};

struct RowColumnStats {
    uint64_t pools = 0;
    uint64_t columns = 0;          // VPLs in
    uint64_t representatives = 0;  // VPLs out
    uint64_t rows = 0;             // summed over pools
    double matrix_seconds = 0.0;   // rows and columns
    double cluster_seconds = 0.0;  // clustering and representatives
};

class RowColumnSampler {
public:
    RowColumnSampler(const RowColumnContext& context, const RowColumnOptions& options);

    // Replaces `vpls` by the representatives of its pools: consecutive runs of options.pool VPLs,
    // the last one possibly shorter, with clusters in proportion to its length. Its pools are
    // numbered first_pool, first_pool + 1, …; pool number k draws from (seed, k) alone.
    void reduce(std::vector<light::Vpl>& vpls, uint64_t first_pool);
    // The same numbered on from the pools reduced before.
    void reduce(std::vector<light::Vpl>& vpls) { reduce(vpls, m_stats.pools); }
    // The number of pools reduce() cuts `count` VPLs into.
    uint64_t pools_of(size_t count) const;
    // The representatives of one pool drawn as pool number `pool`, with `clusters` clusters.
    std::vector<light::Vpl> representatives(std::span<const light::Vpl> pool, uint64_t pool_index,
                                            uint32_t clusters);

    const RowColumnStats& stats() const { return m_stats; }

private:
    RowColumnContext m_context;
    RowColumnOptions m_options;
    float m_d_min2 = 0.0f;
    float m_vsl_r2 = 0.0f;
    RowColumnStats m_stats;
};

}  // namespace mvpl::manylights
