#include "engine/manylights/row_set.h"

#include <algorithm>
#include <cmath>

#include "engine/core/rng.h"
#include "engine/light/specular_chain.h"
#include "engine/scene/camera.h"

namespace mvpl::manylights {

namespace {

// A grid of about `cells` cells with the image's aspect.
void grid_of(double cells, double aspect, int& gx, int& gy) {
    gy = std::max(1, int(std::lround(std::sqrt(cells / aspect))));
    gx = std::max(1, int(std::lround(cells / double(gy))));
}

// One jittered camera ray per cell of a gx × gy grid; the rows of those that find a receiver.
std::vector<Row> trace_grid(const scene::Scene& scene, const trace::Accel& accel,
                            const scene::Camera& camera, const RowSetOptions& options,
                            uint64_t grid_seed, int gx, int gy) {
    Rng rng(grid_seed, 0);
    std::vector<Row> rows;
    rows.reserve(size_t(gx) * size_t(gy));
    for (int j = 0; j < gy; ++j) {
        for (int i = 0; i < gx; ++i) {
            const Vec2 film((float(i) + rng.next_float()) / float(gx) * float(options.width),
                            (float(j) + rng.next_float()) / float(gy) * float(options.height));
            const scene::CameraRay cr =
                scene::generate_camera_ray(camera, options.width, options.height, film);
            Rng chain = light::chain_rng(grid_seed, uint64_t(j * gx + i), 1);
            const light::ChainedReceiver chained = light::make_chained_receiver(
                scene, accel, trace::Ray{cr.origin, cr.direction}, chain, options.chains);
            if (chained.receiver && luminance(chained.throughput) > 0.0f)
                rows.push_back(Row{*chained.receiver, chained.throughput, chained.max_vpl_length});
        }
    }
    return rows;
}

}  // namespace

std::vector<Row> make_rows(const scene::Scene& scene, const trace::Accel& accel,
                           const scene::Camera& camera, const RowSetOptions& options, uint64_t seed,
                           uint64_t pool) {
    const double aspect = double(std::max(options.width, 1)) / double(std::max(options.height, 1));
    const double wanted = double(std::max(options.rows, 1));
    // Streams of their own (the salt), apart from the sampler's and the chains' of the image.
    const uint64_t pool_seed = mix_bits(seed ^ 0x726f77636f6cULL) ^ mix_bits(pool + 1);
    double cells = wanted;
    std::vector<Row> rows;
    for (int pass = 0; pass < kRowGridPasses; ++pass) {
        int gx = 1, gy = 1;
        grid_of(cells, aspect, gx, gy);
        const uint64_t grid_seed = pass == 0 ? pool_seed : mix_bits(pool_seed ^ uint64_t(pass));
        rows = trace_grid(scene, accel, camera, options, grid_seed, gx, gy);
        // Where rays miss (the sky, the background), a finer grid over the image, so that about
        // R rows land on what the camera sees (the finest where none did).
        if (double(rows.size()) >= kRowsFound * wanted) break;
        const double found = std::max(double(rows.size()), 1e-6);
        cells = std::min(cells * wanted / found, kMaxRowCells * wanted);
    }
    return rows;
}

}  // namespace mvpl::manylights
