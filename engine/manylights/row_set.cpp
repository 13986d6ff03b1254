#include "engine/manylights/row_set.h"

#include <algorithm>
#include <cmath>

#include "engine/core/rng.h"
#include "engine/light/specular_chain.h"
#include "engine/scene/camera.h"

namespace mvpl::manylights {

std::vector<Row> make_rows(const scene::Scene& scene, const trace::Accel& accel,
                           const scene::Camera& camera, const RowSetOptions& options, uint64_t seed,
                           uint64_t pool) {
    const double aspect = double(std::max(options.width, 1)) / double(std::max(options.height, 1));
    const int k = std::max(options.rows, 1);
    const int gy = std::max(1, int(std::lround(std::sqrt(double(k) / aspect))));
    const int gx = std::max(1, int(std::lround(double(k) / double(gy))));
    // Streams of their own (the salt), apart from the sampler's and the chains' of the image.
    const uint64_t pool_seed = mix_bits(seed ^ 0x726f77636f6cULL) ^ mix_bits(pool + 1);
    Rng rng(pool_seed, 0);
    std::vector<Row> rows;
    rows.reserve(size_t(gx) * size_t(gy));
    for (int j = 0; j < gy; ++j) {
        for (int i = 0; i < gx; ++i) {
            const Vec2 film((float(i) + rng.next_float()) / float(gx) * float(options.width),
                            (float(j) + rng.next_float()) / float(gy) * float(options.height));
            const scene::CameraRay cr =
                scene::generate_camera_ray(camera, options.width, options.height, film);
            Rng chain = light::chain_rng(pool_seed, uint64_t(j * gx + i), 1);
            const light::ChainedReceiver chained = light::make_chained_receiver(
                scene, accel, trace::Ray{cr.origin, cr.direction}, chain, options.chains);
            if (chained.receiver && luminance(chained.throughput) > 0.0f)
                rows.push_back(Row{*chained.receiver, chained.throughput, chained.max_vpl_length});
        }
    }
    return rows;
}

}  // namespace mvpl::manylights
