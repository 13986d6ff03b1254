#pragma once
// Matrix row-column sampling (Hašan, Pellacini, Bala 2007, "Matrix row-column sampling for the
// many-light problem"): a pool of N VPLs shaded through C weighted cluster representatives chosen
// from an R × N reduced matrix of their contributions to R camera-visible points
// (row_column_sampler.h). The options and their defaults, written once here.
#include <algorithm>
#include <cstdint>

namespace mvpl::manylights {

// R's default: see RowColumnOptions::rows.
inline constexpr uint32_t kDefaultRows = 256;

// C's default: a representative for this many VPLs of a pool. On the Cornell box at 256², 15 s,
// idle machine, medians of seeds (relMSE per pixel / on 8×8 blocks, docs/results.md,
// "Row-column sampling"): N 8192, C 512 read 8.3 / 2.3 ·10⁻⁵ (seeds 1–3) and 8.6 / 3.1 (4–6);
// N 8192, C 1024 8.0 / 3.1; N 16384, C 512 9.2 / 3.1; N 16384, C 1024 7.5 / 1.5 and 8.1 / 1.9;
// N 32768, C 2048 8.1 / 2.7.
inline constexpr uint32_t kVplsPerCluster = 16;

enum class MatrixDevice { automatic, gpu, cpu };
// The smallest pool whose matrix `automatic` evaluates on a CPU implementation of Vulkan: see
// RowColumnOptions::matrix.
inline constexpr uint32_t kGpuMatrixPoolOnCpuDevice = 32768;

struct RowColumnOptions {
    // VPLs per pool; 0 turns row-column sampling off (every VPL shaded). 0 here; `mvpl render`'s
    // `--pool auto` picks N where it was measured to pay (automatic_pool.h). Under mpirun each
    // rank reduces the pools of its own share of the VPLs (VplIntegrator::advance).
    uint32_t pool = 0;
    // R: camera rays on a stratified grid over the image, one jittered ray a cell (a finer grid
    // where rays miss: row_set.h).
    uint32_t rows = kDefaultRows;
    // C: clusters (and so representatives shaded) per full pool; a shorter pool gets its share.
    // 0: pool / kVplsPerCluster (clusters_per_pool()).
    uint32_t clusters = 0;
    // The share of a representative's probability drawn in proportion to VPL power instead of
    // the reduced column norm, so that a VPL that lights pixels no row sees keeps a probability
    // that does not vanish with its norm on the rows. The two rooms at 15 s, six seeds: 0.03 and
    // 0.1 the same error, 0.3 blotches in four (docs/results.md, "Row-column sampling").
    float defensive_share = 0.1f;
    // Dimensions of the sketch the clustering measures columns in (reduced_matrix.h).
    uint32_t sketch_dims = 16;
    // Where the reduced matrix is evaluated (reduced_matrix.h): on the GPU renderer (a distance
    // cube per row: engine/render/matrix_pass.h), with the CPU's Embree rays, or `automatic`:
    // the GPU's, except on a CPU implementation (lavapipe) for pools below
    // kGpuMatrixPoolOnCpuDevice. There a row's cube costs about 0.33 ms (its render passes'
    // thread hand-offs) and the GPU's matrix of four pools measured 0.49 / 0.69 / 0.91 / 1.48 s
    // against the CPU's 0.26 / 0.55 / 1.03 / 2.14 s at N = 8 192 / 16 384 / 32 768 / 65 536
    // (Cornell box, R 256; docs/results.md, "Row-column sampling"). Without a renderer (the
    // oracle) it is the CPU's.
    MatrixDevice matrix = MatrixDevice::automatic;
    // The side of a row cube's face in texels. The matrix only steers which VPLs are drawn, so
    // its visibility may be coarser than the shading's without bias.
    uint32_t row_resolution = 64;

    bool enabled() const { return pool > 0; }
    uint32_t clusters_per_pool() const {
        return clusters > 0 ? clusters : std::max<uint32_t>(1, pool / kVplsPerCluster);
    }
};

}  // namespace mvpl::manylights
