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

}  // namespace mvpl::render
