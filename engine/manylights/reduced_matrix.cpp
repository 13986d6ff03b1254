#include "engine/manylights/reduced_matrix.h"

#include <algorithm>
#include <cmath>

#include "engine/core/parallel.h"
#include "engine/core/rng.h"
#include "engine/light/vpl_contribution.h"

namespace mvpl::manylights {

void reduced_column(const MatrixContext& context, const light::Vpl& vpl, std::span<float> out) {
    const light::PreparedVpl pv = light::prepare_vpl(vpl);
    for (size_t r = 0; r < context.rows.size(); ++r) {
        const Row& row = context.rows[r];
        Rgb c(0.0f);
        if (vpl.path_length <= row.max_vpl_length) {
            c = row.throughput * light::vpl_contribution(*context.accel, row.receiver, pv,
                                                         context.d_min2, context.vsl_r2);
        }
        out[3 * r + 0] = c.r;
        out[3 * r + 1] = c.g;
        out[3 * r + 2] = c.b;
    }
}

ColumnSketches sketch_columns(const MatrixContext& context, std::span<const light::Vpl> vpls,
                              uint32_t dims, uint64_t seed) {
    ColumnSketches s;
    s.dims = std::max<uint32_t>(dims, 1);
    const size_t entries = 3 * context.rows.size();
    // The count sketch's hash: entry k goes to bucket[k] with sign[k].
    std::vector<uint32_t> bucket(entries);
    std::vector<float> sign(entries);
    for (size_t k = 0; k < entries; ++k) {
        const uint64_t h = mix_bits(seed ^ mix_bits(k + 1));
        bucket[k] = uint32_t((h >> 1) % s.dims);
        sign[k] = (h & 1) ? 1.0f : -1.0f;
    }
    s.norms.assign(vpls.size(), 0.0f);
    s.sketch.assign(vpls.size() * s.dims, 0.0f);
    parallel_for(int64_t(vpls.size()), 16, [&](int64_t begin, int64_t end) {
        std::vector<float> column(entries);
        for (int64_t j = begin; j < end; ++j) {
            reduced_column(context, vpls[size_t(j)], column);
            double norm2 = 0.0;
            float* out = &s.sketch[size_t(j) * s.dims];
            for (size_t k = 0; k < entries; ++k) {
                norm2 += double(column[k]) * double(column[k]);
                out[bucket[k]] += sign[k] * column[k];
            }
            s.norms[size_t(j)] = float(std::sqrt(norm2));
        }
    });
    return s;
}

}  // namespace mvpl::manylights
