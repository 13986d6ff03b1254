#include "engine/manylights/reduced_matrix.h"

#include <algorithm>
#include <cmath>

#include "engine/core/parallel.h"
#include "engine/core/rng.h"
#include "engine/light/vpl_contribution.h"

namespace mvpl::manylights {

namespace {

// A column's shadow rays and the rows they belong to, kept from column to column.
struct ColumnScratch {
    std::vector<trace::Ray> rays;
    std::vector<uint32_t> rows;
    std::vector<uint8_t> occluded;
};

// reduced_column with the column's shadow rays traced together: each entry is
// light::vpl_contribution's (unshadowed_contribution, zero where its ray is occluded) bit for bit.
void column_entries(const MatrixContext& context, const light::Vpl& vpl, std::span<float> out,
                    ColumnScratch& scratch) {
    const light::PreparedVpl pv = light::prepare_vpl(vpl);
    const float scale = context.accel->coordinate_scale();
    // The rays of the entries that are not black, written in place.
    scratch.rays.resize(context.rows.size());
    scratch.rows.resize(context.rows.size());
    size_t traced = 0;
    for (size_t r = 0; r < context.rows.size(); ++r) {
        const Row& row = context.rows[r];
        Rgb c(0.0f);
        if (vpl.path_length <= row.max_vpl_length) {
            c = light::unshadowed_contribution(row.receiver, pv, context.d_min2, context.vsl_r2,
                                               scale, scratch.rays[traced]);
            if (!is_black(c)) {
                c = row.throughput * c;
                scratch.rows[traced++] = uint32_t(r);
            }
        }
        out[3 * r + 0] = c.r;
        out[3 * r + 1] = c.g;
        out[3 * r + 2] = c.b;
    }
    scratch.occluded.resize(traced);
    context.accel->occluded(std::span(scratch.rays).first(traced), scratch.occluded);
    for (size_t i = 0; i < traced; ++i) {
        if (!scratch.occluded[i]) continue;
        float* entry = &out[3 * size_t(scratch.rows[i])];
        entry[0] = entry[1] = entry[2] = 0.0f;
    }
}

}  // namespace

void reduced_column(const MatrixContext& context, const light::Vpl& vpl, std::span<float> out) {
    ColumnScratch scratch;
    column_entries(context, vpl, out, scratch);
}

std::vector<uint32_t> sketch_hash(size_t entries, uint32_t dims, uint64_t seed) {
    std::vector<uint32_t> hash(entries);
    for (size_t k = 0; k < entries; ++k) {
        const uint64_t h = mix_bits(seed ^ mix_bits(k + 1));
        hash[k] =
            uint32_t((h >> 1) % std::max<uint32_t>(dims, 1)) | ((h & 1) ? 0u : kSketchNegative);
    }
    return hash;
}

ColumnSketches sketch_columns(const MatrixContext& context, std::span<const light::Vpl> vpls,
                              uint32_t dims, uint64_t seed) {
    ColumnSketches s;
    s.dims = std::max<uint32_t>(dims, 1);
    const size_t entries = 3 * context.rows.size();
    const std::vector<uint32_t> hash = sketch_hash(entries, s.dims, seed);
    std::vector<uint32_t> bucket(entries);
    std::vector<float> sign(entries);
    for (size_t k = 0; k < entries; ++k) {
        bucket[k] = hash[k] & kSketchBucket;
        sign[k] = (hash[k] & kSketchNegative) ? -1.0f : 1.0f;
    }
    s.norms.assign(vpls.size(), 0.0f);
    s.sketch.assign(vpls.size() * s.dims, 0.0f);
    parallel_for(int64_t(vpls.size()), 16, [&](int64_t begin, int64_t end) {
        std::vector<float> column(entries);
        ColumnScratch scratch;
        for (int64_t j = begin; j < end; ++j) {
            column_entries(context, vpls[size_t(j)], column, scratch);
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
