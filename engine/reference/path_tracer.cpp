#include "engine/reference/path_tracer.h"

#include <atomic>
#include <limits>

#include "engine/core/parallel.h"
#include "engine/core/progress.h"
#include "engine/core/sampling.h"
#include "engine/core/timer.h"
#include "engine/scene/camera.h"
#include "engine/trace/interaction.h"
#include "engine/trace/shading_point.h"

namespace mvpl::reference {

PathTracer::PathTracer(const scene::Scene& scene, const trace::Accel& accel,
                       const light::LightSampler& lights)
    : m_scene(scene), m_accel(accel), m_lights(lights) {}

namespace {

Vec2 next_2d(Rng& rng) {
    const float a = rng.next_float();
    return Vec2(a, rng.next_float());
}

// The environment seen along `ray` (the path's segment `depth`), weighted against the light sample
// that could have chosen the same direction, added to L.
void add_environment(const light::LightSampler& lights, const trace::Ray& ray, int depth,
                     float prev_bsdf_pdf, const Rgb& throughput, Rgb& L) {
    const Vec3 w = glm::normalize(ray.direction);
    const Rgb le = lights.environment_radiance(w);
    if (!is_black(le)) {
        const float weight =
            depth > 1 ? power_heuristic(prev_bsdf_pdf, lights.pdf_environment(w)) : 1.0f;
        L += throughput * le * weight;
    }
}

// One light sample at sp (of its diffuse lobe alone when diffuse_only), weighted against the BSDF
// sample that could have found the same light, added to L.
void add_light_sample(const light::LightSampler& lights, const trace::Accel& accel,
                      const trace::ShadingPoint& sp, const Vec3& wo, bool diffuse_only,
                      const Rgb& throughput, Rng& rng, Rgb& L) {
    if (const auto ls = lights.sample_li(sp.p, rng.next_float(), next_2d(rng))) {
        const Vec3 wi = sp.frame.to_local(ls->wi);
        const Rgb f = diffuse_only ? sp.bsdf.eval_diffuse(wo, wi) : sp.bsdf.eval(wo, wi);
        if (!is_black(f) && trace::same_side(ls->wi, sp.ng, wi.z)) {
            const trace::Ray shadow =
                std::isinf(ls->distance)
                    ? trace::spawn_ray(sp.p, sp.ng, ls->wi, accel.coordinate_scale())
                    : trace::spawn_ray_to(sp.p, sp.ng, ls->p, ls->n, accel.coordinate_scale());
            if (!accel.occluded(shadow)) {
                const float bsdf_pdf =
                    diffuse_only ? sp.bsdf.pdf_diffuse(wo, wi) : sp.bsdf.pdf(wo, wi);
                const float weight = ls->is_delta ? 1.0f : power_heuristic(ls->pdf, bsdf_pdf);
                L += throughput * f * std::abs(wi.z) * ls->li * (weight / ls->pdf);
            }
        }
    }
}

}  // namespace

Rgb PathTracer::radiance(const trace::Ray& camera_ray, Rng& rng, int max_depth, int rr_depth,
                         bool from_camera, FirstVertex first) const {
    const bool unlimited = max_depth < 0;
    Rgb L(0.0f);
    Rgb throughput(1.0f);
    trace::Ray ray = camera_ray;
    float prev_bsdf_pdf = 0.0f;  // solid-angle pdf of the BSDF sample that made `ray`
    Vec3 prev_p(0.0f);
    // depth = number of segments of the path up to the current vertex (Mitsuba's convention).
    for (int depth = 1;; ++depth) {
        // The camera does not see the back faces of one-sided materials (glTF doubleSided).
        const std::optional<trace::Hit> hit =
            depth == 1 && from_camera ? m_accel.intersect_camera(ray) : m_accel.intersect(ray);
        if (!hit) {
            add_environment(m_lights, ray, depth, prev_bsdf_pdf, throughput, L);
            break;
        }
        const trace::SurfaceInteraction si = trace::make_interaction(m_scene, *hit, ray);
        const Vec3 wo_world = -glm::normalize(ray.direction);

        // Emission, weighted against the light-sampling strategy that could have found it.
        if (m_accel.materials().is_emissive(si.material)) {
            const Rgb le =
                m_lights.emitted_radiance(si.mesh, si.triangle, hit->barycentric, wo_world);
            if (!is_black(le)) {
                float weight = 1.0f;
                if (depth > 1) {
                    const float light_pdf =
                        m_lights.pdf_li(prev_p, si.mesh, si.triangle, si.p, si.ng);
                    weight = power_heuristic(prev_bsdf_pdf, light_pdf);
                }
                L += throughput * le * weight;
            }
        }
        if (!unlimited && depth >= max_depth) break;

        const trace::ShadingPoint sp = trace::make_shading_point(m_accel.materials(), si);
        const Vec3 wo = sp.frame.to_local(wo_world);
        // Seen from below the shading surface: black, unless it transmits (bsdf.h, "Sides").
        if (!(wo.z > 0.0f) && !sp.bsdf.transmits()) break;

        // The first vertex restricted to its diffuse lobe: light sample, BSDF sample and the MIS
        // weights between them all of that lobe alone.
        const bool diffuse_only = depth == 1 && first == FirstVertex::DiffuseLobe;

        // Next-event estimation: one light sample, the path gets one more segment.
        add_light_sample(m_lights, m_accel, sp, wo, diffuse_only, throughput, rng, L);

        // The same call shape for both (sample_diffuse ignores u_lobe): the numbers are drawn in
        // the same order, so that the two agree bit for bit on Lambertian vertices.
        const auto bs = diffuse_only ? sp.bsdf.sample_diffuse(wo, next_2d(rng), rng.next_float())
                                     : sp.bsdf.sample(wo, next_2d(rng), rng.next_float());
        if (!bs) break;
        const Vec3 wi_world = sp.frame.to_world(bs->wi);
        // A direction on the other geometric side than its shading side would leak through the
        // surface (or miss the transmission that should have carried it).
        if (!trace::same_side(wi_world, sp.ng, bs->wi.z)) break;
        throughput *= bs->weight;
        prev_bsdf_pdf = bs->pdf;
        prev_p = sp.p;
        ray = trace::spawn_ray(sp.p, sp.ng, wi_world, m_accel.coordinate_scale());

        if (depth + 1 >= rr_depth) {
            // Russian roulette on the throughput (pbrt-v3 §14.5.1), never below a 5% survival
            // floor so that white furnaces still terminate.
            const float survive = std::min(0.95f, max_component(throughput));
            if (!(survive > 0.0f) || rng.next_float() >= survive) break;
            throughput /= survive;
        }
    }
    return L;
}

uint64_t PathTracer::host_bytes(const PathTracerOptions& options) {
    // The film (every pixel's generator and sums), the linear RGB image, then the 8-bit sRGB
    // copy and its encoding for a .png output (write_images); an .exr is written from the image.
    return uint64_t(options.width) * uint64_t(options.height) *
           (PathFilm::kBytesPerPixel + sizeof(Rgb) + 2 * 3);
}

Image PathTracer::render(const PathTracerOptions& options, RenderStats* stats,
                         const CameraSampleHook& on_sample) const {
    PathFilm film(options.width, options.height, options.seed);
    Progress progress("reference", int64_t(options.height) * options.spp, options.quiet);
    RenderStats total;
    advance(film, options.spp, options, &total, on_sample, &progress);
    progress.finish();
    if (stats) *stats = total;
    return film.image();
}

void PathTracer::advance(PathFilm& film, int spp, const PathTracerOptions& options,
                         RenderStats* stats, const CameraSampleHook& on_sample,
                         Progress* progress) const {
    const uint64_t rays_before = m_accel.ray_count();
    std::atomic<uint64_t> nonfinite{0};
    Timer timer;
    const int first = film.spp();
    parallel_for(options.height, 1, [&](int64_t y0, int64_t y1) {
        for (int64_t y = y0; y < y1; ++y) {
            for (int x = 0; x < options.width; ++x) {
                const size_t pixel = size_t(y) * size_t(options.width) + size_t(x);
                Rng& rng = film.rng(pixel);
                DVec3& sum = film.sum(pixel);
                for (int s = first; s < first + spp; ++s) {
                    const Vec2 film_point = Vec2(float(x), float(y)) + next_2d(rng);
                    if (on_sample) on_sample(x, int(y), s, film_point);
                    const scene::CameraRay cr = scene::generate_camera_ray(
                        m_scene.camera, options.width, options.height, film_point);
                    const Rgb L = radiance(trace::Ray{cr.origin, cr.direction}, rng,
                                           options.max_depth, options.rr_depth);
                    if (is_finite(L)) {
                        sum += DVec3(L);
                    } else {
                        nonfinite.fetch_add(1, std::memory_order_relaxed);
                    }
                }
            }
            if (progress) progress->advance(spp);
        }
    });
    film.add_spp(spp);
    if (stats) {
        stats->seconds += timer.seconds();
        stats->rays += m_accel.ray_count() - rays_before;
        stats->paths += uint64_t(options.width) * uint64_t(options.height) * uint64_t(spp);
        stats->nonfinite_samples += nonfinite.load();
    }
}

}  // namespace mvpl::reference
