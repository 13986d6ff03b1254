#include "engine/light/specular_chain.h"

#include <cmath>
#include <optional>
#include <vector>

#include "engine/core/sampling.h"
#include "engine/light/light_sampler.h"
#include "engine/scene/camera.h"
#include "engine/trace/shading_point.h"

namespace mvpl::light {
namespace {

// Σ over the scene's punctual lights of f · |cos θi| · I/d² (spot falloff; directional: E) · V at
// a glossy vertex: the light they reflect there directly. A chain continues by sampling the BSDF,
// which never finds a delta light, and the vertex is not lit by VPLs, so without this a point
// light's highlight on a chained surface is lost (measured on assets/glossy: the copper sphere
// 22 % too dark against the path tracer).
Rgb punctual_light(const scene::Scene& scene, const trace::Accel& accel,
                   const trace::ShadingPoint& sp, const Vec3& wo) {
    Rgb sum(0.0f);
    for (const scene::Light& light : scene.lights) {
        const std::optional<LightSample> ls = punctual_li(light, sp.p);
        if (!ls || is_black(ls->li)) continue;
        const Vec3 wi = sp.frame.to_local(ls->wi);
        if (!trace::same_side(ls->wi, sp.ng, wi.z)) continue;
        const Rgb f = sp.bsdf.eval(wo, wi);
        if (is_black(f)) continue;
        const trace::Ray shadow =
            std::isinf(ls->distance)
                ? trace::spawn_ray(sp.p, sp.ng, ls->wi, accel.coordinate_scale())
                : trace::spawn_ray_to(sp.p, sp.ng, ls->p, ls->n, accel.coordinate_scale());
        if (!accel.occluded(shadow)) sum += f * std::abs(wi.z) * ls->li;
    }
    return sum;
}

// One light sample at a glossy vertex for the emitters that a BSDF sample can also find (area
// lights, the environment), weighted by the power heuristic against that BSDF sample (Veach
// 1997), as the path tracer does; a delta light picked is left to punctual_light. Without it a
// small area light seen in a near-mirror was found only by the chain's own BSDF samples: on
// assets/glossy a pixel of the gold sphere (α = 0.0025) read 0.0001 in six seeds of eight
// positions and 40× the path tracer in one of 23 (docs/results.md).
Rgb sampled_light(const trace::Accel& accel, const LightSampler& lights,
                  const trace::ShadingPoint& sp, const Vec3& wo, Rng& rng, bool bsdf_follows) {
    const float u_pick = rng.next_float();
    const Vec2 u(rng.next_float(), rng.next_float());
    const std::optional<LightSample> ls = lights.sample_li(sp.p, u_pick, u);
    if (!ls || ls->is_delta || !(ls->pdf > 0.0f)) return Rgb(0.0f);
    const Vec3 wi = sp.frame.to_local(ls->wi);
    if (!trace::same_side(ls->wi, sp.ng, wi.z)) return Rgb(0.0f);
    const Rgb f = sp.bsdf.eval(wo, wi);
    if (is_black(f)) return Rgb(0.0f);
    const trace::Ray shadow =
        std::isinf(ls->distance)
            ? trace::spawn_ray(sp.p, sp.ng, ls->wi, accel.coordinate_scale())
            : trace::spawn_ray_to(sp.p, sp.ng, ls->p, ls->n, accel.coordinate_scale());
    if (accel.occluded(shadow)) return Rgb(0.0f);
    const float weight = bsdf_follows ? power_heuristic(ls->pdf, sp.bsdf.pdf(wo, wi)) : 1.0f;
    return f * std::abs(wi.z) * ls->li * (weight / ls->pdf);
}

}  // namespace

bool continues_chain(const material::Bsdf& bsdf, const Vec3& wo, const ChainOptions& options) {
    if (!(options.max_roughness >= 0.0f)) return false;
    // VPL shadow maps cannot light through a surface: one that mostly transmits is continued
    // whatever its roughness.
    if (bsdf.transmission_share(wo) >= 0.5f) return true;
    const material::ClosureParams& closure = bsdf.params();
    if (material::closure_type(closure) == material::ClosureType::Lambertian) return false;
    return closure.roughness <= options.max_roughness && bsdf.specular_probability(wo) >= 0.5f;
}

bool scene_may_chain(const scene::Scene& scene, const ChainOptions& options) {
    if (!options.enabled()) return false;
    const std::vector<bool> drawn = scene.drawn_materials();
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        const scene::Material& m = scene.materials[i];
        if (!drawn[i]) continue;
        if (m.metallic < 1.0f && (m.transmission > 0.0f || m.transmission_texture.valid()))
            return true;
        if (m.metallic <= 0.0f && m.specular <= 0.0f) continue;
        if (m.roughness <= options.max_roughness || m.metallic_roughness_texture.valid())
            return true;
    }
    return false;
}

ChainedReceiver make_chained_receiver(const scene::Scene& scene, const trace::Accel& accel,
                                      const trace::Ray& camera_ray, Rng& rng,
                                      const ChainOptions& options, Rgb* emitted,
                                      const LightSampler* lights) {
    const bool unlimited = options.max_depth < 0;
    ChainedReceiver out;
    trace::Ray ray = camera_ray;
    // The BSDF sample that made `ray` and whether a light sample competed with it (MIS).
    float prev_pdf = 0.0f;
    Vec3 prev_p(0.0f);
    bool prev_sampled_light = false;
    for (int bounce = 0;; ++bounce) {
        const int depth = bounce + 1;  // segments from the camera to this vertex
        // What this vertex emits (or the environment, where the ray leaves the scene): the first
        // vertex's as seen directly, the later ones' through the chain's throughput.
        Rgb seen(0.0f);
        EmitterHit hit;
        const std::optional<Receiver> vertex = make_receiver(
            scene, accel, ray, bounce == 0 ? emitted : &seen, bounce == 0, true, &hit);
        if (bounce > 0 && !is_black(seen)) {
            float weight = 1.0f;
            if (prev_sampled_light) {
                const float light_pdf =
                    hit.mesh >= 0 ? lights->pdf_li(prev_p, hit.mesh, hit.triangle, hit.p, hit.ng)
                                  : lights->pdf_environment(glm::normalize(ray.direction));
                weight = power_heuristic(prev_pdf, light_pdf);
            }
            out.chain_emitted += out.throughput * seen * weight;
        }
        if (!vertex) return out;  // left the scene, or seen from below its shading surface
        out.distance += glm::length(vertex->sp.p - ray.origin);
        const trace::ShadingPoint& sp = vertex->sp;
        const Vec3& wo = vertex->wo;
        if (!continues_chain(sp.bsdf, wo, options)) {
            // The inside of a solid or the back of a thin transmissive surface that is not
            // continued: VPLs light only the shading side.
            if (!(wo.z > 0.0f)) return out;
            // A VPL of path_length ℓ lights this vertex through depth + 1 + ℓ segments.
            if (!unlimited && options.max_depth - depth - 1 < 0) return out;
            out.receiver = vertex;
            out.bounces = uint32_t(bounce);
            if (!unlimited) out.max_vpl_length = uint32_t(options.max_depth - depth - 1);
            return out;
        }
        // A glossy vertex: punctual lights reach it through depth + 1 segments.
        out.continued = true;
        const bool lit = unlimited || depth + 1 <= options.max_depth;
        if (!scene.lights.empty() && lit)
            out.chain_emitted += out.throughput * punctual_light(scene, accel, sp, wo);
        // The next vertex is worth finding only if it may still add light.
        const bool follows = bounce < options.max_bounces && lit;
        prev_sampled_light = lights != nullptr && !lights->empty() && lit;
        if (prev_sampled_light)
            out.chain_emitted +=
                out.throughput * sampled_light(accel, *lights, sp, wo, rng, follows);
        if (!follows) return out;
        const Vec2 u(rng.next_float(), rng.next_float());
        const auto bs = sp.bsdf.sample(wo, u, rng.next_float());
        if (!bs) return out;
        const Vec3 wi_world = sp.frame.to_world(bs->wi);
        // A direction on the other geometric side than its shading side would leak through the
        // surface (as the path tracer).
        if (!trace::same_side(wi_world, sp.ng, bs->wi.z)) return out;
        out.throughput *= bs->weight;
        if (is_black(out.throughput)) return out;
        prev_pdf = bs->pdf;
        prev_p = sp.p;
        ray = trace::spawn_ray(sp.p, sp.ng, wi_world, accel.coordinate_scale());
    }
}

namespace {

trace::Ray ray_through(const scene::Camera& camera, int width, int height, int x, int y,
                       const Vec2& offset) {
    const scene::CameraRay cr = scene::generate_camera_ray(
        camera, width, height, Vec2(float(x) + offset.x, float(y) + offset.y));
    return trace::Ray{cr.origin, cr.direction};
}

}  // namespace

bool pixel_centre_continues(const scene::Scene& scene, const trace::Accel& accel,
                            const scene::Camera& camera, int width, int height, int x, int y,
                            const ChainOptions& options) {
    const std::optional<Receiver> centre = make_receiver(
        scene, accel, ray_through(camera, width, height, x, y, Vec2(0.5f)), nullptr, true, true);
    return centre && continues_chain(centre->sp.bsdf, centre->wo, options);
}

Rgb pixel_chain_emission(const scene::Scene& scene, const trace::Accel& accel,
                         const scene::Camera& camera, int width, int height, int x, int y,
                         bool centre_continues, const ChainedReceiver& first, Rng& rng,
                         const ChainOptions& options, const LightSampler* lights) {
    const int samples = options.emission_samples;
    if (samples <= 1 || !centre_continues) return first.chain_emitted;
    Rgb sum = first.chain_emitted;
    for (int k = 1; k < samples; ++k) {
        const Vec2 offset(rng.next_float(), rng.next_float());
        sum += make_chained_receiver(scene, accel, ray_through(camera, width, height, x, y, offset),
                                     rng, options, nullptr, lights)
                   .chain_emitted;
    }
    return sum / float(samples);
}

}  // namespace mvpl::light
