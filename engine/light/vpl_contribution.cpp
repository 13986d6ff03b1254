#include "engine/light/vpl_contribution.h"

#include <algorithm>
#include <cmath>

#include "engine/light/virtual_sphere.h"
#include "engine/trace/interaction.h"
#include "shaders/shared/lobe_clamp.h"
#include "shaders/shared/spot_falloff.h"
#include "shaders/shared/virtual_sphere.h"
#include "shaders/shared/vpl_pair.h"

namespace mvpl::light {
namespace {

using shared::math::VplFactors;

// The VPL's own factors towards the receiver (shaders/shared/vpl_pair.h), ω = w the unit
// direction from the VPL to the receiver: f_j's lobes integrated over the virtual sphere of
// spread s² = spread2 (virtual_sphere.h); f_diffuse only where the pair is clamped lobe by lobe.
VplFactors vpl_factors(const PreparedVpl& pv, const Vec3& w, float spread2, bool by_lobe) {
    const Vpl& v = *pv.vpl;
    VplFactors e{1.0f, Rgb(1.0f), Rgb(1.0f)};
    if (v.type == VplType::Spot)
        e.emitter = shared::spot_falloff(v.cos_inner, v.cos_outer, glm::dot(v.normal, w));
    if (v.type == VplType::Area || v.type == VplType::Surface)
        e.emitter = std::max(0.0f, glm::dot(v.normal, w));
    if (v.type != VplType::Surface || !(e.emitter > 0.0f)) return e;
    const Vec3 w_local = pv.frame.to_local(w);
    if (by_lobe) e.f_diffuse = pv.bsdf->eval_diffuse(pv.wi_local, w_local);
    if (spread2 > 0.0f && !v.closure.is_lambertian()) {
        e.f = material::Bsdf(widen_closure(v.closure, spread2)).eval(pv.wi_local, w_local);
    } else {
        e.f = pv.bsdf->eval(pv.wi_local, w_local);
    }
    return e;
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

Rgb unshadowed_contribution(const Receiver& receiver, const PreparedVpl& pv, float d_min2,
                            float vsl_r2, float coordinate_scale, trace::Ray& shadow) {
    const trace::ShadingPoint& sp = receiver.sp;
    const Vpl& v = *pv.vpl;
    Vec3 to_light = -v.normal;  // unit, receiver → VPL
    float d2 = 1.0f;            // a directional VPL's, unclamped (vpl_pair.h)
    float spread2 = 0.0f;       // of the virtual sphere, for both lobes (virtual_sphere.h)
    // A VSL pair with a glossy lobe in it, clamped lobe by lobe (lobe_clamp.h).
    bool by_lobe = false;
    VplFactors e{1.0f, Rgb(1.0f), Rgb(1.0f)};
    if (v.type != VplType::Directional) {
        const Vec3 d = v.position - sp.p;
        d2 = glm::dot(d, d);
        if (!(d2 > 0.0f)) return Rgb(0.0f);
        to_light = d / std::sqrt(d2);
    }
    // The receiver's own tests first: each returns black on its own, so their order does not
    // change the result, and these two are cheaper than the VPL's BSDF in vpl_factors.
    if (!(glm::dot(to_light, sp.ng) > 0.0f)) return Rgb(0.0f);  // below the geometric surface
    const Vec3 wi = sp.frame.to_local(to_light);
    if (!(wi.z > 0.0f)) return Rgb(0.0f);  // cos θ' = max(0, n'·(−ω))
    if (v.type != VplType::Directional) {
        if (is_spherical(v.type)) spread2 = shared::vsl_spread2(vsl_r2, d2);
        by_lobe = shared::math::clamps_by_lobe(
            spread2, d_min2,
            sp.bsdf.has_glossy() || (v.type == VplType::Surface && pv.bsdf->has_glossy()));
        e = vpl_factors(pv, -to_light, spread2, by_lobe);
    } else {
        d_min2 = 0.0f;  // at infinity: the unclamped d² = 1 of vpl_pair.h
    }
    if (!(e.emitter > 0.0f) || is_black(e.f)) return Rgb(0.0f);
    const Rgb f =
        spread2 > 0.0f && !sp.bsdf.params().is_lambertian()
            ? material::Bsdf(widen_closure(sp.bsdf.params(), spread2)).eval(receiver.wo, wi)
            : sp.bsdf.eval(receiver.wo, wi);
    if (is_black(f)) return Rgb(0.0f);
    const Rgb c =
        by_lobe ? shared::math::vpl_pair_by_lobe(v.power, f, sp.bsdf.eval_diffuse(receiver.wo, wi),
                                                 wi.z, e, d2, vsl_r2, d_min2)
                : shared::math::vpl_pair(v.power, f, wi.z, e, d2, d_min2);
    if (is_black(c)) return Rgb(0.0f);
    const bool on_surface = v.type == VplType::Area || v.type == VplType::Surface;
    shadow = v.type == VplType::Directional
                 ? trace::spawn_ray(sp.p, sp.ng, to_light, coordinate_scale)
                 : trace::spawn_ray_to(sp.p, sp.ng, v.position, on_surface ? v.normal : Vec3(0.0f),
                                       coordinate_scale);
    return c;
}

Rgb vpl_contribution(const trace::Accel& accel, const Receiver& receiver, const PreparedVpl& pv,
                     float d_min2, float vsl_r2) {
    trace::Ray shadow;
    const Rgb c =
        unshadowed_contribution(receiver, pv, d_min2, vsl_r2, accel.coordinate_scale(), shadow);
    if (is_black(c) || accel.occluded(shadow)) return Rgb(0.0f);
    return c;
}

}  // namespace mvpl::light
