#include "engine/reference/vpl_gather.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "engine/core/parallel.h"
#include "engine/core/progress.h"
#include "engine/core/timer.h"
#include "engine/light/vpl_contribution.h"
#include "engine/scene/camera.h"
#include "engine/trace/interaction.h"
#include "engine/trace/ray.h"

namespace mvpl::reference {

namespace {

Rgb shade(const scene::Scene& scene, const trace::Accel& accel,
          const std::vector<light::PreparedVpl>& vpls, double scale, const trace::Ray& camera_ray,
          float d_min2, bool show_emitters) {
    Rgb L(0.0f);
    const std::optional<light::Receiver> receiver =
        light::make_receiver(scene, accel, camera_ray, show_emitters ? &L : nullptr);
    if (!receiver) return L;
    DVec3 sum(0.0);
    for (const light::PreparedVpl& pv : vpls)
        sum += DVec3(light::vpl_contribution(accel, *receiver, pv, d_min2));
    return L + Rgb(sum * scale);
}

}  // namespace

Image gather_vpls(const scene::Scene& scene, const trace::Accel& accel, const light::VplSet& vpls,
                  const GatherOptions& options, GatherStats* stats) {
    Timer timer;
    const uint64_t rays_before = accel.ray_count();
    std::vector<light::PreparedVpl> prepared;
    prepared.reserve(vpls.vpls.size());
    for (const light::Vpl& v : vpls.vpls)
        prepared.push_back(light::prepare_vpl(v));
    const float d_min = options.clamp * scene.bounds().diagonal();
    const bool show_emitters = options.max_depth < 0 || options.max_depth >= 1;
    Image image(options.width, options.height);
    Progress progress("vpl gather", options.height, options.quiet);
    parallel_for(options.height, 1, [&](int64_t y0, int64_t y1) {
        for (int64_t y = y0; y < y1; ++y) {
            for (int x = 0; x < options.width; ++x) {
                const Vec2 film(float(x) + 0.5f, float(y) + 0.5f);
                const scene::CameraRay cr =
                    scene::generate_camera_ray(scene.camera, options.width, options.height, film);
                image.at(x, int(y)) =
                    shade(scene, accel, prepared, vpls.scale, trace::Ray{cr.origin, cr.direction},
                          d_min * d_min, show_emitters);
            }
            progress.advance();
        }
    });
    progress.finish();
    if (stats) {
        stats->seconds = timer.seconds();
        stats->rays = accel.ray_count() - rays_before;
    }
    return image;
}

}  // namespace mvpl::reference
