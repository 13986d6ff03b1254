#include "engine/light/vpl_contribution.h"

#include <algorithm>
#include <cmath>

#include "engine/light/virtual_sphere.h"
#include "engine/trace/interaction.h"
#include "shaders/shared/virtual_sphere.h"

namespace mvpl::light {
namespace {

// The VPL's own factor towards the receiver: spot(axis·ω), max(0, n_j·ω) or
// f_j(ω_in, ω)·max(0, n_j·ω) (vpl.h), ω the unit direction from the VPL to the receiver; f_j's
// lobe integrated over the virtual sphere of spread s² = spread2 (virtual_sphere.h). `diffuse`,
// if given, receives the part through f_j's diffuse lobe alone (all of an area VPL's factor,
// whose emission counts as diffuse).
Rgb emitter_factor(const PreparedVpl& pv, const Vec3& w, float spread2, Rgb* diffuse = nullptr) {
    const Vpl& v = *pv.vpl;
    switch (v.type) {
        case VplType::Point:
            return Rgb(1.0f);
        case VplType::Spot: {
            // KHR_lights_punctual falloff from the VPL's own cone (spot_attenuation's).
            const float scale = 1.0f / std::max(1e-3f, v.cos_inner - v.cos_outer);
            const float t = std::clamp((glm::dot(v.normal, w) - v.cos_outer) * scale, 0.0f, 1.0f);
            return Rgb(t * t);
        }
        case VplType::Area: {
            const Rgb f(std::max(0.0f, glm::dot(v.normal, w)));
            if (diffuse) *diffuse = f;
            return f;
        }
        case VplType::Surface: {
            const float cos_j = glm::dot(v.normal, w);
            if (!(cos_j > 0.0f)) return Rgb(0.0f);
            const Vec3 w_local = pv.frame.to_local(w);
            if (diffuse) *diffuse = pv.bsdf->eval_diffuse(pv.wi_local, w_local) * cos_j;
            if (spread2 > 0.0f && !v.closure.is_lambertian()) {
                const material::Bsdf widened(widen_closure(v.closure, spread2));
                return widened.eval(pv.wi_local, w_local) * cos_j;
            }
            return pv.bsdf->eval(pv.wi_local, w_local) * cos_j;
        }
        case VplType::Directional:
            break;
    }
    return Rgb(0.0f);
}

}  // namespace

PreparedVpl prepare_vpl(const Vpl& vpl) {
    PreparedVpl pv;
    pv.vpl = &vpl;
    if (vpl.type == VplType::Surface) {
        pv.bsdf.emplace(vpl.closure);
        pv.frame = Frame(vpl.shading_normal);
        pv.wi_local = pv.frame.to_local(vpl.wi);
    }
    return pv;
}

std::optional<Receiver> make_receiver(const scene::Scene& scene, const trace::Accel& accel,
                                      const trace::Ray& ray, Rgb* emitted, bool from_camera,
                                      bool transmissive_back, EmitterHit* emitter) {
    const std::optional<trace::Hit> hit =
        from_camera ? accel.intersect_camera(ray) : accel.intersect(ray);
    if (!hit) {
        // The environment seen where the ray leaves the scene.
        if (emitted && scene.environment.active())
            *emitted += scene.environment.lookup(glm::normalize(ray.direction));
        return std::nullopt;
    }
    const trace::SurfaceInteraction si = trace::make_interaction(scene, *hit, ray);
    // Emitters emit from their front face only, whatever doubleSided says.
    if (emitted && si.front_face) {
        material::SurfacePoint point;
        point.uv0 = si.uv0;
        point.uv1 = si.uv1;
        point.color = si.color;
        *emitted += accel.materials().emission(si.material, point);
        if (emitter) *emitter = EmitterHit{si.mesh, si.triangle, si.p, si.ng};
    }
    Receiver r{trace::make_shading_point(accel.materials(), si), Vec3(0.0f, 0.0f, 1.0f)};
    r.wo = r.sp.frame.to_local(-glm::normalize(ray.direction));
    // Seen from below the shading surface: black, but where a chain may pass through.
    if (!(r.wo.z > 0.0f) && !(transmissive_back && r.sp.bsdf.transmits())) return std::nullopt;
    return r;
}

Rgb vpl_contribution(const trace::Accel& accel, const Receiver& receiver, const PreparedVpl& pv,
                     float d_min2, float vsl_r2) {
    const trace::ShadingPoint& sp = receiver.sp;
    const Vpl& v = *pv.vpl;
    Vec3 to_light;  // unit, receiver → VPL
    float inv_d2 = 1.0f;
    Rgb factor(1.0f);
    float spread2 = 0.0f;  // of the virtual sphere, for both lobes (virtual_sphere.h)
    // A VSL pair with a glossy lobe in it, clamped lobe by lobe (lobe_clamp): its diffuse part.
    bool by_lobe = false;
    Rgb factor_diffuse(0.0f);
    float inv_glossy_d2 = 1.0f;
    if (v.type == VplType::Directional) {
        to_light = -v.normal;
    } else {
        const Vec3 d = v.position - sp.p;
        const float dist2 = glm::dot(d, d);
        if (!(dist2 > 0.0f)) return Rgb(0.0f);
        to_light = d / std::sqrt(dist2);
        inv_d2 = 1.0f / std::max(dist2, d_min2);
        if (is_spherical(v.type)) spread2 = shared::vsl_spread2(vsl_r2, dist2);
        by_lobe = spread2 > 0.0f && d_min2 > 0.0f &&
                  (sp.bsdf.has_glossy() || (v.type == VplType::Surface && pv.bsdf->has_glossy()));
        if (by_lobe) inv_glossy_d2 = 1.0f / shared::vsl_glossy_d2(dist2, vsl_r2, d_min2);
        factor = emitter_factor(pv, -to_light, spread2, by_lobe ? &factor_diffuse : nullptr);
    }
    if (is_black(factor)) return Rgb(0.0f);
    if (!(glm::dot(to_light, sp.ng) > 0.0f)) return Rgb(0.0f);  // below the geometric surface
    const Vec3 wi = sp.frame.to_local(to_light);
    if (!(wi.z > 0.0f)) return Rgb(0.0f);  // cos θ' = max(0, n'·(−ω))
    const Rgb f =
        spread2 > 0.0f && !sp.bsdf.params().is_lambertian()
            ? material::Bsdf(widen_closure(sp.bsdf.params(), spread2)).eval(receiver.wo, wi)
            : sp.bsdf.eval(receiver.wo, wi);
    if (is_black(f)) return Rgb(0.0f);
    Rgb c;
    if (by_lobe) {
        // The diffuse × diffuse product clamped by d_min, the rest (every product with a widened
        // glossy lobe) by the sphere (shared::vsl_glossy_d2).
        const Rgb diffuse = sp.bsdf.eval_diffuse(receiver.wo, wi) * factor_diffuse;
        const Rgb glossy = glm::max(f * factor - diffuse, Rgb(0.0f));
        c = v.power * (diffuse * (wi.z * inv_d2) + glossy * (wi.z * inv_glossy_d2));
    } else {
        c = v.power * f * factor * (wi.z * inv_d2);
    }
    if (is_black(c)) return Rgb(0.0f);
    const bool on_surface = v.type == VplType::Area || v.type == VplType::Surface;
    const trace::Ray shadow =
        v.type == VplType::Directional
            ? trace::spawn_ray(sp.p, sp.ng, to_light, accel.coordinate_scale())
            : trace::spawn_ray_to(sp.p, sp.ng, v.position, on_surface ? v.normal : Vec3(0.0f),
                                  accel.coordinate_scale());
    if (accel.occluded(shadow)) return Rgb(0.0f);
    return c;
}

}  // namespace mvpl::light
