#include "engine/light/specular_chain.h"

#include <algorithm>
#include <vector>

#include "engine/trace/interaction.h"
#include "engine/trace/shading_point.h"

namespace mvpl::light {
namespace {

// Emitted radiance at a hit, front face only (as make_receiver).
Rgb emitted_at(const trace::Accel& accel, const trace::SurfaceInteraction& si) {
    if (!si.front_face) return Rgb(0.0f);
    material::SurfacePoint point;
    point.uv0 = si.uv0;
    point.uv1 = si.uv1;
    point.color = si.color;
    return accel.materials().emission(si.material, point);
}

}  // namespace

bool continues_chain(const material::Bsdf& bsdf, const Vec3& wo, const ChainOptions& options) {
    if (!(options.max_roughness >= 0.0f)) return false;
    const material::ClosureParams& closure = bsdf.params();
    if (material::closure_type(closure) == material::ClosureType::Lambertian) return false;
    return closure.roughness <= options.max_roughness && bsdf.specular_probability(wo) >= 0.5f;
}

bool scene_may_chain(const scene::Scene& scene, const ChainOptions& options) {
    if (!options.enabled()) return false;
    std::vector<bool> drawn(scene.materials.size(), false);
    for (const scene::Mesh& mesh : scene.meshes) {
        if (!mesh.indices.empty() && mesh.material >= 0 && size_t(mesh.material) < drawn.size())
            drawn[size_t(mesh.material)] = true;
    }
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        const scene::Material& m = scene.materials[i];
        if (!drawn[i] || (m.metallic <= 0.0f && m.specular <= 0.0f)) continue;
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
        const std::optional<trace::Hit> hit =
            bounce == 0 ? accel.intersect_camera(ray) : accel.intersect(ray);
        if (!hit) {
            if (scene.environment.active()) {
                const Rgb le = scene.environment.lookup(glm::normalize(ray.direction));
                if (bounce == 0 && emitted) *emitted += le;
                if (bounce > 0) out.chain_emitted += out.throughput * le;
            }
            return out;
        }
        const trace::SurfaceInteraction si = trace::make_interaction(scene, *hit, ray);
        if (bounce == 0 && emitted) *emitted += emitted_at(accel, si);
        if (bounce > 0) out.chain_emitted += out.throughput * emitted_at(accel, si);

        const trace::ShadingPoint sp = trace::make_shading_point(accel.materials(), si);
        const Vec3 wo = sp.frame.to_local(-glm::normalize(ray.direction));
        if (!(wo.z > 0.0f)) return out;  // seen from below the shading surface: black
        if (!continues_chain(sp.bsdf, wo, options)) {
            // A VPL of path_length ℓ lights this vertex through depth + 1 + ℓ segments.
            if (!unlimited && options.max_depth - depth - 1 < 0) return out;
            out.receiver = Receiver{sp, wo};
            out.bounces = uint32_t(bounce);
            if (!unlimited) out.max_vpl_length = uint32_t(options.max_depth - depth - 1);
            return out;
        }
        // A glossy vertex: the next one is worth finding only if it may still add light.
        out.continued = true;
        if (bounce >= options.max_bounces || (!unlimited && depth + 1 > options.max_depth))
            return out;
        const Vec2 u(rng.next_float(), rng.next_float());
        const auto bs = sp.bsdf.sample(wo, u, rng.next_float());
        if (!bs) return out;
        const Vec3 wi_world = sp.frame.to_world(bs->wi);
        // A direction below the geometric surface would leak through it (as the path tracer).
        if (glm::dot(wi_world, sp.ng) <= 0.0f) return out;
        out.throughput *= bs->weight;
        if (is_black(out.throughput)) return out;
        ray = trace::spawn_ray(sp.p, sp.ng, wi_world);
    }
}

}  // namespace mvpl::light
