#include "engine/sampler/light_tracer.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/light/path_partition.h"
#include "engine/trace/interaction.h"
#include "engine/trace/ray.h"
#include "engine/trace/shading_point.h"

namespace mvpl::sampler {

namespace {

Vec2 next_2d(SampleStream& u) {
    const float a = u.next();
    return Vec2(a, u.next());
}

bool usable(const Rgb& power) {
    return is_finite(power) && !is_black(power);
}

}  // namespace

LightTracer::LightTracer(const scene::Scene& scene, const trace::Accel& accel,
                         const light::LightSampler& lights, const LightTracerOptions& options)
    : m_scene(scene), m_accel(accel), m_lights(lights), m_options(options) {}

int LightTracer::max_path_length() const {
    if (m_options.max_depth < 0) return std::numeric_limits<int>::max();
    return std::max(m_options.max_depth - 2, -1);
}

light::Vpl LightTracer::emitter_vpl(const light::EmissionSample& es) const {
    // The emitter VPL (path_length 0): the light itself, or the sampled point of an area light.
    light::Vpl emitter;
    emitter.position = es.p;
    emitter.power = es.le;
    emitter.path_length = 0;
    switch (es.type) {
        case light::EmitterType::Triangle:
            emitter.type = light::VplType::Area;
            emitter.normal = emitter.shading_normal = es.n;
            break;
        case light::EmitterType::Point:
            emitter.type = light::VplType::Point;
            break;
        case light::EmitterType::Spot: {
            const scene::Light& light = m_scene.lights[m_lights.emitters()[es.emitter].light];
            emitter.type = light::VplType::Spot;
            emitter.normal = light.direction;
            emitter.cos_inner = std::cos(light.inner_cone);
            emitter.cos_outer = std::cos(light.outer_cone);
            break;
        }
        case light::EmitterType::Directional:
        case light::EmitterType::Environment:  // a directional light of the sampled direction
            emitter.type = light::VplType::Directional;
            emitter.normal = es.direction;
            break;
    }
    return emitter;
}

size_t LightTracer::trace_emitter(SampleStream& u, std::vector<light::Vpl>& out) const {
    const float u_pick = u.next();
    const Vec2 u_pos = next_2d(u);
    const Vec2 u_dir = next_2d(u);
    if (max_path_length() < 0) return 0;
    const std::optional<light::EmissionSample> es = m_lights.sample_le(u_pick, u_pos, u_dir);
    if (!es) return 0;
    const light::Vpl emitter = emitter_vpl(*es);
    if (!usable(emitter.power)) return 0;
    out.push_back(emitter);
    return 1;
}

size_t LightTracer::trace(SampleStream& u, std::vector<light::Vpl>& out) const {
    const size_t first = out.size();
    // The emission dimensions are always read, so that the layout of u never shifts.
    const float u_pick = u.next();
    const Vec2 u_pos = next_2d(u);
    const Vec2 u_dir = next_2d(u);
    const int max_length = max_path_length();
    if (max_length < 0) return 0;
    const std::optional<light::EmissionSample> es = m_lights.sample_le(u_pick, u_pos, u_dir);
    if (!es) return 0;

    const light::Vpl emitter = emitter_vpl(*es);
    trace::Ray ray{es->p, es->direction};
    if (es->type == light::EmitterType::Triangle)
        ray = trace::spawn_ray(es->p, es->n, es->direction, m_accel.coordinate_scale());
    if (usable(emitter.power)) out.push_back(emitter);

    Rgb beta = es->throughput;
    const float beta_start = max_component(beta);
    if (!(beta_start > 0.0f) || !is_finite(beta)) return out.size() - first;
    const light::ChainOptions vpl_class = light::path_chain_class(m_options.specular, es->type);
    for (int length = 1; length <= max_length; ++length) {
        const std::optional<trace::Hit> hit = m_accel.intersect(ray);
        if (!hit) break;
        const trace::SurfaceInteraction si = trace::make_interaction(m_scene, *hit, ray);
        const trace::ShadingPoint sp = trace::make_shading_point(m_accel.materials(), si);
        const Vec3 wi_world = -glm::normalize(ray.direction);
        const Vec3 wi = sp.frame.to_local(wi_world);
        const float cos_geometric = glm::dot(wi_world, sp.ng);
        // The back of a one-sided material (ng not flipped) is black: the path ends, as in the
        // path tracer; so does light that the shading normal puts on the other side than the
        // geometry. Transmissive closures are seen from both sides (material/bsdf.h).
        const bool front = wi.z > 0.0f;
        if (!(front || sp.bsdf.transmits()) || !trace::same_side(wi_world, sp.ng, wi.z)) break;
        beta *= wi.z / cos_geometric;  // shading cosine at arrival (header comment)

        // A VPL reflects towards the side it was lit from, as the GPU shades it: its closure
        // keeps no transmission (the light a surface transmits is followed by the path instead),
        // and none is left on the back of a transmissive surface, where the GPU could not tell
        // its sides apart. (On smooth glass it is a near-mirror's VPL: the GPU's glossy term,
        // unless the caustic tracer carries the light of such vertices: options().specular.)
        light::Vpl vpl;
        vpl.type = light::VplType::Surface;
        vpl.position = sp.p;
        vpl.normal = sp.ng;
        vpl.shading_normal = sp.frame.n;
        vpl.wi = wi_world;
        vpl.power = beta;
        vpl.closure = sp.bsdf.params();
        vpl.closure.transmission = Rgb(0.0f);
        vpl.path_length = uint32_t(length);
        if (usable(vpl.power) && light::leaves_vpl(sp.bsdf, wi, vpl_class)) out.push_back(vpl);
        if (length == max_length) break;

        const Vec2 u_bsdf = next_2d(u);
        const float u_lobe = u.next();
        const float u_rr = u.next();
        const std::optional<material::BsdfSample> bs =
            sp.bsdf.sample(wi, u_bsdf, u_lobe, material::Transport::Importance);
        if (!bs) break;
        const Vec3 wo_world = sp.frame.to_world(bs->wi);
        // On the geometric side its shading side says, or it would leak through the surface.
        if (!trace::same_side(wo_world, sp.ng, bs->wi.z)) break;
        const float cos_out = glm::dot(wo_world, sp.ng);
        beta *= bs->weight * (cos_out / bs->wi.z);  // f·|n_g·ω_out|/pdf
        if (!is_finite(beta)) break;

        if (length + 3 >= m_options.rr_depth) {
            // Russian roulette on the throughput relative to the path's start (pbrt-v3 §14.5.1),
            // with the path tracer's 5% floor on termination.
            const float survive = std::min(0.95f, max_component(beta) / beta_start);
            if (!(survive > 0.0f) || u_rr >= survive) break;
            beta /= survive;
        }
        ray = trace::spawn_ray(sp.p, sp.ng, wo_world, m_accel.coordinate_scale());
    }
    return out.size() - first;
}

}  // namespace mvpl::sampler
