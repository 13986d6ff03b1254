#include "engine/sampler/importance.h"

#include <algorithm>
#include <cmath>

#include "engine/core/color.h"
#include "engine/core/rng.h"
#include "engine/light/specular_chain.h"
#include "engine/scene/camera.h"

namespace mvpl::sampler {

Importance::Importance(const scene::Scene& scene, const trace::Accel& accel,
                       const scene::Camera& camera, const ImportanceOptions& options)
    : m_accel(accel),
      m_relative(options.relative),
      m_absolute_share(std::clamp(options.absolute_share, 0.0, 1.0)) {
    // A grid of gx × gy strata with the image's aspect and about K cells, one jittered ray each.
    const double aspect = double(std::max(options.width, 1)) / double(std::max(options.height, 1));
    const int k = std::max(options.points, 1);
    const int gy = std::max(1, int(std::lround(std::sqrt(double(k) / aspect))));
    const int gx = std::max(1, int(std::lround(double(k) / double(gy))));
    Rng rng(mix_bits(options.seed ^ 0x696d706f7274ULL), 0);
    m_rays = gx * gy;
    for (int j = 0; j < gy; ++j) {
        for (int i = 0; i < gx; ++i) {
            const Vec2 film((float(i) + rng.next_float()) / float(gx) * float(options.width),
                            (float(j) + rng.next_float()) / float(gy) * float(options.height));
            const scene::CameraRay cr =
                scene::generate_camera_ray(camera, options.width, options.height, film);
            // The chain's own generator (not the renderer's per-pixel one): the target needs a
            // representative rough end per stratum, not the image's.
            Rng chain_rng = light::chain_rng(options.seed, uint64_t(j * gx + i), 0);
            const light::ChainedReceiver chained = light::make_chained_receiver(
                scene, accel, trace::Ray{cr.origin, cr.direction}, chain_rng, options.chains);
            if (chained.receiver && luminance(chained.throughput) > 0.0f) {
                m_points.push_back(
                    Point{*chained.receiver, chained.throughput, chained.max_vpl_length});
            }
        }
    }
    m_weights.assign(m_points.size(), 1.0);
    const float d_min = options.clamp * scene.bounds().diagonal();
    m_d_min2 = d_min * d_min;
    const float vsl_radius = options.vsl_radius * scene.bounds().diagonal();
    m_vsl_r2 = vsl_radius * vsl_radius;
}

float Importance::luminance_at(const Point& point, const light::PreparedVpl& pv) const {
    if (pv.vpl->path_length > point.max_vpl_length) return 0.0f;
    return luminance(point.throughput *
                     light::vpl_contribution(m_accel, point.receiver, pv, m_d_min2, m_vsl_r2));
}

double Importance::evaluate(std::span<const light::Vpl> vpls) const {
    double sum = 0.0;
    for (const light::Vpl& v : vpls) {
        const light::PreparedVpl pv = light::prepare_vpl(v);
        for (size_t k = 0; k < m_points.size(); ++k)
            sum += m_weights[k] * double(luminance_at(m_points[k], pv));
    }
    return m_rays > 0 ? sum / double(m_rays) : 0.0;
}

void Importance::evaluate_points(std::span<const light::Vpl> vpls,
                                 std::span<float> per_point) const {
    for (const light::Vpl& v : vpls) {
        const light::PreparedVpl pv = light::prepare_vpl(v);
        for (size_t k = 0; k < m_points.size(); ++k)
            per_point[k] += luminance_at(m_points[k], pv);
    }
}

double Importance::evaluate(std::span<const float> per_point) const {
    double sum = 0.0;
    for (size_t k = 0; k < m_points.size(); ++k)
        sum += m_weights[k] * double(per_point[k]);
    return m_rays > 0 ? sum / double(m_rays) : 0.0;
}

void Importance::set_point_radiance(std::span<const double> radiance) {
    m_weights.assign(m_points.size(), 1.0);
    if (!m_relative || radiance.size() != m_points.size() || m_points.empty()) return;
    double mean = 0.0;
    for (double l : radiance)
        mean += l;
    mean /= double(radiance.size());
    if (!(mean > 0.0) || !std::isfinite(mean)) return;
    double sum = 0.0, mass = 0.0;
    for (size_t k = 0; k < m_points.size(); ++k) {
        // 0.1·mean bounds the weight of unlit points to 10/mean; on the two-room scene it put
        // 33% of Metropolis surface VPLs in the camera's room where 1·mean put 30%.
        m_weights[k] = 1.0 / (std::max(radiance[k], 0.0) + 0.1 * mean);
        mass += m_weights[k] * std::max(radiance[k], 0.0);
    }
    // The mix: the relative weights' mass (Σ w·L) and the plain one's (Σ L) in the proportion
    // 1 − share : share.
    const double total = mean * double(radiance.size());
    for (double& w : m_weights) {
        w = (1.0 - m_absolute_share) * w / mass + m_absolute_share / total;
        sum += w;
    }
    for (double& w : m_weights)
        w *= double(m_points.size()) / sum;
}

}  // namespace mvpl::sampler
