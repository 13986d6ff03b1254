#pragma once
// How `mvpl render` and the Python module's render (python/) cut a render into chunks of sampler
// work: the same chunks give the same VPLs and the same float sums, so both give the same image.
#include <algorithm>
#include <cstdint>

namespace mvpl::cli {

// Seconds of sampling + shading aimed at per progressive chunk under --time-budget: long enough
// that a Metropolis chain merges its repeats over several steps, short enough that the last
// chunk overshoots the budget by little.
constexpr double kChunkSeconds = 0.5;
// The same with row-column sampling (--pool): a pool of 8192 VPLs is about 0.35 s of reduced matrix
// on two cores at 256 rows (docs/results.md, "Row-column sampling"); the last chunk is cut to the
// budget all the same.
constexpr double kPoolChunkSeconds = 2.0;

// Light paths or chain steps per chunk of a fixed-size render: whole blocks of the Monte Carlo
// tracer's 256 paths (so that the VPLs are those of one call), two of them so that both cores
// trace, and few enough that SIGINT ends a render soon (interrupt.h: the chunk in flight is
// finished): ≈ 1 400 VPLs, 2 s at 32² and 4 s at 512² on two lavapipe cores, where the
// per-VPL shadow maps dominate. Fixed, not measured: a render's chunks, and so its float sums,
// are the same on every run.
constexpr uint64_t kStreamChunkUnits = 512;

// The next chunk of work units: about kChunkSeconds at the rate measured so far, never past the
// remaining budget's worth, at least one unit.
inline uint64_t next_chunk(uint64_t done, double elapsed, double remaining, uint64_t first,
                           double chunk_seconds) {
    if (done == 0 || !(elapsed > 0.0)) return first;
    const double per_unit = elapsed / double(done);
    const double seconds = std::min(chunk_seconds, remaining);
    // At most 2^20 units a chunk, however cheap they were so far.
    return std::clamp<uint64_t>(uint64_t(std::min(seconds / per_unit, 1e9)), 1, uint64_t(1) << 20);
}

}  // namespace mvpl::cli
