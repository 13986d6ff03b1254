#include "engine/light/specular_chain.h"

#include <cmath>
#include <optional>
#include <vector>

#include "engine/light/light_sampler.h"
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
        const trace::Ray shadow = std::isinf(ls->distance)
                                      ? trace::spawn_ray(sp.p, sp.ng, ls->wi)
                                      : trace::spawn_ray_to(sp.p, sp.ng, ls->p, ls->n);
        if (!accel.occluded(shadow)) sum += f * std::abs(wi.z) * ls->li;
    }
    return sum;
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
                                      const ChainOptions& options, Rgb* emitted) {
    const bool unlimited = options.max_depth < 0;
    ChainedReceiver out;
    trace::Ray ray = camera_ray;
    for (int bounce = 0;; ++bounce) {
        const int depth = bounce + 1;  // segments from the camera to this vertex
        // What this vertex emits (or the environment, where the ray leaves the scene): the first
        // vertex's as seen directly, the later ones' through the chain's throughput.
        Rgb seen(0.0f);
        const std::optional<Receiver> vertex =
            make_receiver(scene, accel, ray, bounce == 0 ? emitted : &seen, bounce == 0, true);
        if (bounce > 0) out.chain_emitted += out.throughput * seen;
        if (!vertex) return out;  // left the scene, or seen from below its shading surface
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
        if (!scene.lights.empty() && (unlimited || depth + 1 <= options.max_depth))
            out.chain_emitted += out.throughput * punctual_light(scene, accel, sp, wo);
        // The next vertex is worth finding only if it may still add light.
        if (bounce >= options.max_bounces || (!unlimited && depth + 1 > options.max_depth))
            return out;
        const Vec2 u(rng.next_float(), rng.next_float());
        const auto bs = sp.bsdf.sample(wo, u, rng.next_float());
        if (!bs) return out;
        const Vec3 wi_world = sp.frame.to_world(bs->wi);
        // A direction on the other geometric side than its shading side would leak through the
        // surface (as the path tracer).
        if (!trace::same_side(wi_world, sp.ng, bs->wi.z)) return out;
        out.throughput *= bs->weight;
        if (is_black(out.throughput)) return out;
        ray = trace::spawn_ray(sp.p, sp.ng, wi_world);
    }
}

}  // namespace mvpl::light
