#pragma once
// The reduced matrix of a pool (Hašan et al. 2007): entry (r, j) is VPL j's contribution to
// row r — light::vpl_contribution, the CPU oracle's own code (BSDFs, clamp, virtual spheres,
// Embree visibility), times the row's chain throughput — RGB, so a column ρ_j has 3R entries. A
// column's shadow rays are traced together, as one Embree ray stream: the same entries, bit for
// bit, in about two thirds of the time of a call a ray (docs/results.md, "Row-column sampling").
// Only what the clustering needs is kept of it: each column's norm ‖ρ_j‖ and a count sketch of
// ρ_j in D dimensions (Charikar, Chen, Farach-Colton 2002: entry k added with a random sign into
// bucket h(k)), whose inner products estimate the columns' without bias. R × N × 3 floats would be
// 400 MB at R = 256, N = 131 072; the sketch is N × D.
#include <cstdint>
#include <span>
#include <vector>

#include "engine/light/vpl.h"
#include "engine/manylights/row_set.h"
#include "engine/trace/accel.h"

namespace mvpl::manylights {

// What is fixed per pool for evaluating columns.
struct MatrixContext {
    const trace::Accel* accel = nullptr;
    std::span<const Row> rows;
    float d_min2 = 0.0f;  // (clamp · scene diagonal)²
    float vsl_r2 = 0.0f;  // (virtual sphere radius)²
};

// Column j: the 3R entries (r, g, b of row 0, then row 1, …) of `vpl`'s contributions.
void reduced_column(const MatrixContext& context, const light::Vpl& vpl, std::span<float> out);

struct ColumnSketches {
    uint32_t dims = 0;
    std::vector<float> norms;   // per column, ‖ρ_j‖ over its 3R entries
    std::vector<float> sketch;  // column j at [j · dims, (j + 1) · dims)
};

// The count sketch's hash of 3R entries: entry k goes to bucket hash[k] & kSketchBucket, subtracted
// where kSketchNegative is set (the GPU's matrix reads the same, matrix_template.glsl).
inline constexpr uint32_t kSketchNegative = 0x80000000u;
inline constexpr uint32_t kSketchBucket = 0x7fffffffu;
std::vector<uint32_t> sketch_hash(size_t entries, uint32_t dims, uint64_t seed);

// Every column's norm and sketch, in parallel over columns; the same whatever the thread count.
ColumnSketches sketch_columns(const MatrixContext& context, std::span<const light::Vpl> vpls,
                              uint32_t dims, uint64_t seed);

// Where a pool's columns are evaluated: sketch_columns on the CPU, or another evaluator with the
// same entries up to its visibility (the GPU's rows' cubes: engine/integrator/gpu_columns.h).
class ColumnEvaluator {
public:
    virtual ~ColumnEvaluator() = default;
    // sketch_columns' result, with the hash sketch_hash(3R, dims, seed).
    virtual ColumnSketches sketch(const MatrixContext& context, std::span<const light::Vpl> vpls,
                                  uint32_t dims, uint64_t seed) = 0;
};

}  // namespace mvpl::manylights
