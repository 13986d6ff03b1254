#include "engine/reference/vpl_gather.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "engine/core/parallel.h"
#include "engine/core/progress.h"
#include "engine/core/timer.h"
#include "engine/material/bsdf.h"
#include "engine/material/material_eval.h"
#include "engine/reference/shading_point.h"
#include "engine/scene/camera.h"
#include "engine/trace/interaction.h"
#include "engine/trace/ray.h"

namespace mvpl::reference {

namespace {

// The VPL's own factor towards the receiver: spot(axis·ω), max(0, n_j·ω) or
// f_j(ω_in, ω)·max(0, n_j·ω) (vpl.h), ω the unit direction from the VPL to the receiver.
Rgb emitter_factor(const PreparedVpl& pv, const Vec3& w) {
    const light::Vpl& v = *pv.vpl;
    switch (v.type) {
        case light::VplType::Point:
            return Rgb(1.0f);
        case light::VplType::Spot: {
            // KHR_lights_punctual falloff from the VPL's own cone (light::spot_attenuation's).
            const float scale = 1.0f / std::max(1e-3f, v.cos_inner - v.cos_outer);
            const float t = std::clamp((glm::dot(v.normal, w) - v.cos_outer) * scale, 0.0f, 1.0f);
            return Rgb(t * t);
        }
        case light::VplType::Area:
            return Rgb(std::max(0.0f, glm::dot(v.normal, w)));
        case light::VplType::Surface: {
            const float cos_j = glm::dot(v.normal, w);
            if (!(cos_j > 0.0f)) return Rgb(0.0f);
            return pv.bsdf->eval(pv.wi_local, pv.frame.to_local(w)) * cos_j;
        }
        case light::VplType::Directional:
            break;
    }
    return Rgb(0.0f);
}

Rgb shade(const scene::Scene& scene, const trace::Accel& accel,
          const std::vector<PreparedVpl>& vpls, double scale, const trace::Ray& camera_ray,
          float d_min2, bool show_emitters) {
    Rgb L(0.0f);
    const std::optional<Receiver> receiver =
        make_receiver(scene, accel, camera_ray, show_emitters ? &L : nullptr);
    if (!receiver) return L;
    DVec3 sum(0.0);
    for (const PreparedVpl& pv : vpls)
        sum += DVec3(vpl_contribution(accel, *receiver, pv, d_min2));
    return L + Rgb(sum * scale);
}

}  // namespace

PreparedVpl prepare_vpl(const light::Vpl& vpl) {
    PreparedVpl pv;
    pv.vpl = &vpl;
    if (vpl.type == light::VplType::Surface) {
        pv.bsdf.emplace(vpl.closure);
        pv.frame = Frame(vpl.shading_normal);
        pv.wi_local = pv.frame.to_local(vpl.wi);
    }
    return pv;
}

std::optional<Receiver> make_receiver(const scene::Scene& scene, const trace::Accel& accel,
                                      const trace::Ray& camera_ray, Rgb* emitted) {
    const std::optional<trace::Hit> hit = accel.intersect(camera_ray);
    if (!hit) return std::nullopt;
    const trace::SurfaceInteraction si = trace::make_interaction(scene, *hit, camera_ray);
    const scene::Material& material = scene.materials[si.material];
    // Emitters emit from their front face only, whatever doubleSided says.
    if (emitted && material.is_emissive() && si.front_face)
        *emitted += material::resolve_emission(material, scene.textures, {si.uv0, si.uv1});
    Receiver r{make_shading_point(scene, si), Vec3(0.0f, 0.0f, 1.0f)};
    r.wo = r.sp.frame.to_local(-glm::normalize(camera_ray.direction));
    if (!(r.wo.z > 0.0f)) return std::nullopt;  // seen from below the shading surface: black
    return r;
}

Rgb vpl_contribution(const trace::Accel& accel, const Receiver& receiver, const PreparedVpl& pv,
                     float d_min2) {
    const ShadingPoint& sp = receiver.sp;
    const light::Vpl& v = *pv.vpl;
    Vec3 to_light;  // unit, receiver → VPL
    float inv_d2 = 1.0f;
    Rgb factor(1.0f);
    if (v.type == light::VplType::Directional) {
        to_light = -v.normal;
    } else {
        const Vec3 d = v.position - sp.p;
        const float dist2 = glm::dot(d, d);
        if (!(dist2 > 0.0f)) return Rgb(0.0f);
        to_light = d / std::sqrt(dist2);
        inv_d2 = 1.0f / std::max(dist2, d_min2);
        factor = emitter_factor(pv, -to_light);
    }
    if (is_black(factor)) return Rgb(0.0f);
    if (!(glm::dot(to_light, sp.ng) > 0.0f)) return Rgb(0.0f);  // below the geometric surface
    const Vec3 wi = sp.frame.to_local(to_light);
    if (!(wi.z > 0.0f)) return Rgb(0.0f);  // cos θ' = max(0, n'·(−ω))
    const Rgb f = sp.bsdf.eval(receiver.wo, wi);
    if (is_black(f)) return Rgb(0.0f);
    const Rgb c = v.power * f * factor * (wi.z * inv_d2);
    if (is_black(c)) return Rgb(0.0f);
    const bool on_surface = v.type == light::VplType::Area || v.type == light::VplType::Surface;
    const trace::Ray shadow =
        v.type == light::VplType::Directional
            ? trace::spawn_ray(sp.p, sp.ng, to_light)
            : trace::spawn_ray_to(sp.p, sp.ng, v.position, on_surface ? v.normal : Vec3(0.0f));
    if (accel.occluded(shadow)) return Rgb(0.0f);
    return c;
}

Image gather_vpls(const scene::Scene& scene, const trace::Accel& accel, const light::VplSet& vpls,
                  const GatherOptions& options, GatherStats* stats) {
    Timer timer;
    const uint64_t rays_before = accel.ray_count();
    std::vector<PreparedVpl> prepared;
    prepared.reserve(vpls.vpls.size());
    for (const light::Vpl& v : vpls.vpls)
        prepared.push_back(prepare_vpl(v));
    const float d_min = options.clamp * scene.bounds().diagonal();
    const bool show_emitters = options.max_depth < 0 || options.max_depth >= 1;
    Image image(options.width, options.height);
    Progress progress("vpl gather", options.height, options.quiet);
    parallel_for(options.height, 1, [&](int64_t y0, int64_t y1) {
        for (int64_t y = y0; y < y1; ++y) {
            for (int x = 0; x < options.width; ++x) {
                const Vec2 film(float(x) + 0.5f, float(y) + 0.5f);
                const scene::CameraRay cr =
                    scene::generate_camera_ray(scene.camera, options.width, options.height, film);
                image.at(x, int(y)) =
                    shade(scene, accel, prepared, vpls.scale, trace::Ray{cr.origin, cr.direction},
                          d_min * d_min, show_emitters);
            }
            progress.advance();
        }
    });
    progress.finish();
    if (stats) {
        stats->seconds = timer.seconds();
        stats->rays = accel.ray_count() - rays_before;
    }
    return image;
}

}  // namespace mvpl::reference
