#include "engine/integrator/clamp_compensation.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "engine/core/parallel.h"
#include "engine/core/rng.h"
#include "engine/light/specular_chain.h"
#include "engine/light/vpl_contribution.h"
#include "engine/reference/pass_mean.h"
#include "engine/reference/path_tracer.h"
#include "engine/scene/camera.h"
#include "engine/trace/ray.h"

namespace mvpl::integrator {

using reference::PassMean;  // engine/reference/pass_mean.h
using reference::PathTracer;

struct ClampCompensation::Impl {
    const scene::Scene& scene;
    const trace::Accel& accel;
    CompensationOptions options;
    scene::Camera camera;  // options.camera's, copied: the caller may move its own
    PathTracer path_tracer;
    float d_min = 0.0f;
    std::vector<const scene::Light*> punctual;  // point and spot lights
    std::vector<Rgb> pass_image;                // the pass under way
    PassMean mean;                              // of the passes done

    Impl(const scene::Scene& s, const trace::Accel& a, const light::LightSampler& lights,
         const CompensationOptions& o)
        : scene(s),
          accel(a),
          options(o),
          camera(o.camera ? *o.camera : s.camera),
          path_tracer(s, a, lights),
          d_min(o.clamp * s.bounds().diagonal()),
          pass_image(size_t(o.width) * size_t(o.height)),
          mean(o.width, o.height) {
        for (const scene::Light& l : s.lights) {
            if (l.type == scene::LightType::Point || l.type == scene::LightType::Spot)
                punctual.push_back(&l);
        }
    }

    // VPL light needs a light path vertex and the receiver: at least two segments.
    bool active() const {
        return d_min > 0.0f && (options.max_depth < 0 || options.max_depth >= 2);
    }

    // The share of a point at distance d that the clamped estimate leaves out.
    float missing(float d) const { return std::max(0.0f, 1.0f - (d * d) / (d_min * d_min)); }

    // Punctual lights nearer than d_min: I·(1/d² − 1/d_min²)·f·cos θ, visibility exact.
    Rgb punctual_part(const light::Receiver& r) const {
        Rgb out(0.0f);
        for (const scene::Light* l : punctual) {
            const Vec3 to_light = l->position - r.sp.p;
            const float d = glm::length(to_light);
            if (!(d > 0.0f) || d >= d_min) continue;
            const Vec3 wi_world = to_light / d;
            const Vec3 wi = r.sp.frame.to_local(wi_world);
            if (wi.z <= 0.0f || glm::dot(wi_world, r.sp.ng) <= 0.0f) continue;
            float falloff = 1.0f;
            if (l->type == scene::LightType::Spot)
                falloff = light::spot_attenuation(*l, glm::dot(l->direction, -wi_world));
            if (falloff <= 0.0f) continue;
            const Rgb f = r.sp.bsdf.eval(r.wo, wi);
            if (is_black(f)) continue;
            if (accel.occluded(trace::spawn_ray_to(r.sp.p, r.sp.ng, l->position, Vec3(0.0f),
                                                   accel.coordinate_scale())))
                continue;
            out += f * wi.z * l->intensity * falloff * (missing(d) / (d * d));
        }
        return out;
    }

    Rgb sample_pixel(int x, int y, Rng& rng) const {
        const Vec2 film(float(x) + rng.next_float(), float(y) + rng.next_float());
        const scene::CameraRay cr =
            scene::generate_camera_ray(camera, options.width, options.height, film);
        const trace::Ray camera_ray{cr.origin, cr.direction};
        // The receiver the VPLs light: the first hit, or the rough end of its chain.
        std::optional<light::Receiver> r;
        Rgb throughput(1.0f);
        int bounces = 0;
        if (options.chains.enabled()) {
            light::ChainedReceiver c =
                light::make_chained_receiver(scene, accel, camera_ray, rng, options.chains);
            r = std::move(c.receiver);
            throughput = c.throughput;
            bounces = int(c.bounces);
        } else {
            r = light::make_receiver(scene, accel, camera_ray);
        }
        if (!r) return Rgb(0.0f);
        return throughput * compensate(*r, rng, bounces);
    }

    // What the clamp leaves out at receiver r, reached after `bounces` glossy vertices.
    Rgb compensate(const light::Receiver& r, Rng& rng, int bounces) const {
        // The path tracer goes on from the receiver: one segment fewer than the whole path.
        const int depth = options.max_depth < 0 ? -1 : options.max_depth - 1 - bounces;
        if (depth == 0) return Rgb(0.0f);
        Rgb out = punctual_part(r);
        const float u_lobe = rng.next_float();
        const Vec2 u(rng.next_float(), rng.next_float());
        // Lobe by lobe (VSLs): f_D from its own density, L_D beyond (clamp_compensation.h).
        const bool by_lobe = options.vsl_radius > 0.0f;
        const std::optional<material::BsdfSample> bs =
            by_lobe ? r.sp.bsdf.sample_diffuse(r.wo, u) : r.sp.bsdf.sample(r.wo, u, u_lobe);
        if (!bs) return out;
        const Vec3 wi_world = glm::normalize(r.sp.frame.to_world(bs->wi));
        if (glm::dot(wi_world, r.sp.ng) <= 0.0f) return out;
        trace::Ray ray = trace::spawn_ray(r.sp.p, r.sp.ng, wi_world, accel.coordinate_scale());
        ray.tmax = d_min;
        const std::optional<trace::Hit> hit = accel.intersect(ray);
        if (!hit) return out;
        const Rgb L = path_tracer.radiance(
            ray, rng, depth, std::max(1, options.rr_depth - 1), false,
            by_lobe ? reference::FirstVertex::DiffuseLobe : reference::FirstVertex::AllLobes);
        return out + bs->weight * L * missing(hit->t);
    }

    void add_pass() {
        const uint32_t pass = mean.passes();
        std::fill(pass_image.begin(), pass_image.end(), Rgb(0.0f));
        if (active()) {
            const uint64_t global =
                uint64_t(options.first_pass) + uint64_t(pass) * uint64_t(options.pass_stride);
            const uint64_t seed = mix_bits(options.seed ^ (global << 32));
            parallel_for(options.height, 1, [&](int64_t y0, int64_t y1) {
                for (int64_t y = y0; y < y1; ++y) {
                    for (int x = 0; x < options.width; ++x) {
                        const size_t pixel = size_t(y) * size_t(options.width) + size_t(x);
                        Rng rng(seed, pixel);
                        const Rgb c = sample_pixel(x, int(y), rng);
                        if (is_finite(c)) pass_image[pixel] = c;
                    }
                }
            });
        }
        mean.add(pass_image);
    }
};

ClampCompensation::ClampCompensation(const scene::Scene& scene, const trace::Accel& accel,
                                     const light::LightSampler& lights,
                                     const CompensationOptions& options)
    : m_impl(std::make_unique<Impl>(scene, accel, lights, options)) {}

ClampCompensation::~ClampCompensation() = default;

void ClampCompensation::add_pass() {
    m_impl->add_pass();
}

uint32_t ClampCompensation::passes() const {
    return m_impl->mean.passes();
}

bool ClampCompensation::active() const {
    return m_impl->active();
}

Image ClampCompensation::image(uint32_t* passes) const {
    return m_impl->mean.mean(passes);
}

}  // namespace mvpl::integrator
