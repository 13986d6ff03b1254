#include "engine/reference/vpl_gather.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "engine/core/parallel.h"
#include "engine/core/progress.h"
#include "engine/core/timer.h"
#include "engine/light/light_sampler.h"
#include "engine/light/vpl_contribution.h"
#include "engine/reference/interleaved_gather.h"
#include "engine/scene/camera.h"
#include "engine/trace/interaction.h"
#include "engine/trace/ray.h"

namespace mvpl::reference {

namespace {

// What every pixel shares.
struct Gather {
    const scene::Scene& scene;
    const trace::Accel& accel;
    const std::vector<light::PreparedVpl>& vpls;
    const GatherOptions& options;
    double scale;
    float d_min2;
    bool show_emitters;
    float vsl_r2;
    const light::LightSampler* lights;  // for the chains' light samples (specular_chain.h)
};

// The pixel (x, y): per sub-pixel position a camera ray, the emitted radiance if the position is
// one the emission is averaged over, and the contributions of the list's VPLs at that position.
Rgb shade_pixel(const Gather& g, int x, int y) {
    const SubpixelSchedule& schedule = g.options.subpixel;
    const uint64_t first = g.options.first_vpl;
    const size_t n = g.vpls.size();
    const uint64_t emission_positions = schedule.positions_after(first + n);
    const uint64_t lo = g.show_emitters || n == 0 ? 0 : schedule.position_of(first);
    uint64_t hi = g.show_emitters ? emission_positions : 0;
    if (n > 0) hi = std::max(hi, schedule.position_of(first + n - 1) + 1);
    Rgb emitted(0.0f);
    DVec3 sum(0.0);
    // Which pixels the chains' light gets extra samples in (specular_chain.h): once per pixel.
    const bool centre_continues =
        g.show_emitters && g.options.chains.enabled() && g.options.chains.emission_samples > 1 &&
        light::pixel_centre_continues(g.scene, g.accel, g.scene.camera, g.options.width,
                                      g.options.height, x, y, g.options.chains);
    size_t i = 0;  // the first VPL not yet shaded; its position is ≥ p
    for (uint64_t p = lo; p < hi; ++p) {
        size_t end = i;
        while (end < n && schedule.position_of(first + end) == p)
            ++end;
        const bool emission = g.show_emitters && p < emission_positions;
        if (end == i && !emission) continue;
        const Vec2 offset = schedule.position(p);
        const Vec2 film(float(x) + offset.x, float(y) + offset.y);
        const scene::CameraRay cr =
            scene::generate_camera_ray(g.scene.camera, g.options.width, g.options.height, film);
        const trace::Ray ray{cr.origin, cr.direction};
        Rng rng = light::chain_rng(g.options.chain_seed,
                                   uint64_t(y) * uint64_t(g.options.width) + uint64_t(x), p);
        const light::ChainedReceiver chained = light::make_chained_receiver(
            g.scene, g.accel, ray, rng, g.options.chains, emission ? &emitted : nullptr, g.lights);
        if (emission)
            emitted += light::pixel_chain_emission(
                g.scene, g.accel, g.scene.camera, g.options.width, g.options.height, x, y,
                centre_continues, chained, rng, g.options.chains, g.lights);
        if (chained.receiver) {
            DVec3 part(0.0);
            for (size_t k = i; k < end; ++k) {
                if (g.vpls[k].vpl->path_length > chained.max_vpl_length) continue;
                part += DVec3(light::vpl_contribution(g.accel, *chained.receiver, g.vpls[k],
                                                      g.d_min2, g.vsl_r2));
            }
            sum += part * DVec3(chained.throughput);
        }
        i = end;
    }
    return emitted / float(emission_positions) + Rgb(sum * g.scale);
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
    const float vsl_radius = options.vsl_radius * scene.bounds().diagonal();
    std::optional<light::LightSampler> lights;
    if (light::scene_may_chain(scene, options.chains)) lights.emplace(scene);
    const Gather g{scene,
                   accel,
                   prepared,
                   options,
                   vpls.scale,
                   d_min * d_min,
                   options.max_depth < 0 || options.max_depth >= 1,
                   vsl_radius * vsl_radius,
                   lights ? &*lights : nullptr};
    // Interleaved: the pixels shade the emission alone (an empty list after all of them, so
    // that it is averaged over the same positions, the chains' emission included) and the
    // filtered VPL sum is added.
    const bool interleaved = options.interleave > 1;
    const std::vector<light::PreparedVpl> none;
    GatherOptions emission_only = options;
    emission_only.first_vpl = options.first_vpl + prepared.size();
    const Gather ge{scene,    accel,           none,     emission_only, vpls.scale,
                    g.d_min2, g.show_emitters, g.vsl_r2, g.lights};
    Image image(options.width, options.height);
    Progress progress("vpl gather", options.height, options.quiet);
    parallel_for(options.height, 1, [&](int64_t y0, int64_t y1) {
        for (int64_t y = y0; y < y1; ++y) {
            for (int x = 0; x < options.width; ++x)
                image.at(x, int(y)) = shade_pixel(interleaved ? ge : g, x, int(y));
            progress.advance();
        }
    });
    progress.finish();
    if (interleaved) {
        const Image sum = interleaved_vpl_sum(scene, accel, prepared, options, g.d_min2, g.lights);
        for (int y = 0; y < options.height; ++y) {
            for (int x = 0; x < options.width; ++x)
                image.at(x, y) += Rgb(DVec3(sum.at(x, y)) * vpls.scale);
        }
    }
    if (stats) {
        stats->seconds = timer.seconds();
        stats->rays = accel.ray_count() - rays_before;
    }
    return image;
}

}  // namespace mvpl::reference
