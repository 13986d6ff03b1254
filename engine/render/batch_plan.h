#pragma once
// How VplRenderer::accumulate() cuts the VPLs of a call into shadow/shading batches: by the batch
// size, by sub-pixel position (engine/core/subpixel.h) and, for a rank's share under mpirun
// (engine/cluster) with interleaving, where the VPLs' indices stop being consecutive.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/render/vpl_renderer.h"

namespace mvpl::render {

// A shadow/shading batch: `count` VPLs from `first` of an accumulate() call, all at one sub-pixel
// position.
struct Slice {
    size_t first = 0;
    size_t count = 0;
    uint64_t position = 0;
};

// The batches of `count` VPLs that follow `shaded` others since begin(): at most options.batch
// each and, with jitter, cut where the sub-pixel position changes, so that every VPL is shaded
// at the position of its index since begin(), however the calls split the VPLs. With `index`
// (a rank's share), VPL i's index is index[i] instead of shaded + i.
std::vector<Slice> plan_batches(size_t count, uint64_t shaded, const RenderOptions& options,
                                std::span<const uint64_t> index = {});

// The batches that share a sub-pixel position (RenderOptions::batches_per_position) by default in
// a scene of `triangles`: one per kTrianglesPerPosition started, at least kMinBatchesPerPosition
// and at most kMaxBatchesPerPosition. A position costs a G-buffer and, interleaved, a filter
// pass (interleave_filter.h), whatever its batches: on lavapipe about 15 ms on the Cornell box at
// 256² against 34 ms for a batch of 32 VPLs, and for the dragon's 202 k triangles a 49 ms
// G-buffer at 512² (every triangle at full detail, where shadow maps draw levels of detail)
// against ≈ 190 ms a batch. Two batches a position made the Cornell box 1.19× faster and its
// error at 10 s lower, four the dragon ≈ 1.2× faster (docs/results.md, "Sub-pixel positions").
inline constexpr size_t kTrianglesPerPosition = 65536;
inline constexpr uint32_t kMinBatchesPerPosition = 2;
inline constexpr uint32_t kMaxBatchesPerPosition = 8;
uint32_t default_batches_per_position(size_t triangles);

}  // namespace mvpl::render
