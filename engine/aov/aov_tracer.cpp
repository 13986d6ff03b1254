#include "engine/aov/aov_tracer.h"

#include <algorithm>

#include "engine/light/specular_chain.h"
#include "engine/scene/camera.h"
#include "engine/trace/interaction.h"
#include "engine/trace/shading_point.h"

namespace mvpl::aov {

namespace {

// glTF's base colour: the closure holds its diffuse share (1 − t) · base and the transmission
// t · base apart (material/closure.h).
Rgb albedo_of(const material::Bsdf& bsdf) {
    const material::ClosureParams c = material::clamp_to_valid_ranges(bsdf.params());
    const Rgb sum = c.base_color + c.transmission;
    return Rgb(std::min(sum.r, 1.0f), std::min(sum.g, 1.0f), std::min(sum.b, 1.0f));
}

AovSample sample_of(const trace::ShadingPoint& sp, float depth) {
    return AovSample{albedo_of(sp.bsdf), sp.frame.n, sp.p, depth};
}

}  // namespace

AovTracer::AovTracer(const scene::Scene& scene, const trace::Accel& accel,
                     const scene::Camera& camera, int width, int height,
                     const light::ChainOptions& chains)
    : m_scene(scene), m_accel(accel), m_camera(camera), m_width(width), m_height(height) {
    if (chains.enabled() && light::scene_may_chain(scene, chains)) {
        m_chains = chains;
        m_lights = std::make_unique<light::LightSampler>(scene);
    }
}

AovTracer::~AovTracer() = default;

AovSample AovTracer::sample(const Vec2& film, Rng& chain) const {
    const scene::CameraRay cr = scene::generate_camera_ray(m_camera, m_width, m_height, film);
    const trace::Ray ray{cr.origin, cr.direction};
    const std::optional<trace::Hit> hit = m_accel.intersect_camera(ray);
    if (!hit) return {};
    // The ray starts on the near plane, on the line from the eye.
    const float lead = glm::length(cr.origin - m_camera.position());
    const trace::SurfaceInteraction si = trace::make_interaction(m_scene, *hit, ray);
    const trace::ShadingPoint sp = trace::make_shading_point(m_accel.materials(), si);
    if (m_chains.enabled()) {
        const Vec3 wo = sp.frame.to_local(-ray.direction);
        const bool seen = wo.z > 0.0f || sp.bsdf.transmits();
        if (seen && light::continues_chain(sp.bsdf, wo, m_chains)) {
            // The chain from the start, as the chain layer traces it: same generator, same path.
            const light::ChainedReceiver c = light::make_chained_receiver(
                m_scene, m_accel, ray, chain, m_chains, nullptr, m_lights.get());
            if (!c.receiver) return {};
            return sample_of(c.receiver->sp, lead + c.distance);
        }
    }
    return sample_of(sp, lead + glm::length(sp.p - ray.origin));
}

}  // namespace mvpl::aov
