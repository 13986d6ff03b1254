#pragma once
// The rows of the reduced matrix (Hašan et al. 2007): R points the camera sees, one jittered
// camera ray per cell of a grid over the image with the image's aspect, so that the rows spread
// over the image as its pixels do. Where many rays find nothing (a model before the sky covers
// part of the image), the grid is made finer until about R of them find a surface: with R cells
// DamagedHelmet at 256² kept 24–27 rows of 256, and its representatives were chosen from those.
// Where the renderer continues a glossy pixel through a specular chain, the row is the chain's
// rough end, weighted by the chain's throughput and lit only by the VPLs that max_depth lets light
// it, as the renderer shades it (light/specular_chain.h).
#include <cstdint>
#include <vector>

#include "engine/core/color.h"
#include "engine/core/image_size.h"
#include "engine/light/chain_options.h"
#include "engine/light/vpl_contribution.h"
#include "engine/manylights/row_column_options.h"
#include "engine/scene/scene.h"
#include "engine/trace/accel.h"

namespace mvpl::manylights {

// make_rows: the grid is refined at most this many times, until kRowsFound · R rays find a
// receiver, and holds at most kMaxRowCells · R cells.
inline constexpr int kRowGridPasses = 3;
inline constexpr double kRowsFound = 0.9;
inline constexpr double kMaxRowCells = 64.0;

struct Row {
    light::Receiver receiver;
    Rgb throughput{1.0f};  // the chain's (1 without a chain)
    uint32_t max_vpl_length = UINT32_MAX;
};

struct RowSetOptions {
    int width = int(kDefaultImageWidth);  // the image the rows spread over
    int height = int(kDefaultImageHeight);
    int rows =
        int(kDefaultRows);  // cells of the grid; rays that find nothing to light leave no row
    light::ChainOptions chains;
};

// The rows of one pool: the jitter inside the cells and the chains' samples are drawn from
// `seed` and `pool` alone. About options.rows of them where the camera sees anything.
std::vector<Row> make_rows(const scene::Scene& scene, const trace::Accel& accel,
                           const scene::Camera& camera, const RowSetOptions& options, uint64_t seed,
                           uint64_t pool);

}  // namespace mvpl::manylights
