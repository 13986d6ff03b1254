// light::vpl_contribution in GLSL: one VPL's contribution to a receiver, with the formulas of
// engine/light/vpl.h. Shared by the shading pass (shading_template.glsl: a pixel's receiver, the
// VPL's shadow cube) and the reduced matrix (matrix_template.glsl: a row's receiver, the row's
// cube). Included after GpuVpl, the push constants pc (flags, d_min2, vsl_r2) and the generated
// closures; the including stage defines the visibility functions declared below.
#include "shared/vpl_pair.h"
//@if spot
#include "shared/spot_falloff.h"
//@endif
//@if glossy
#include "shared/virtual_sphere.h"
#include "shared/lobe_clamp.h"

// light::widen_closure (engine/light/virtual_sphere.cpp): the lobe integrated over a virtual
// sphere of spread s² = spread2.
Closure widen_closure(Closure c, float spread2) {
    Closure w = c;
    w.roughness = vsl_roughness(roughness_to_alpha(c.roughness), spread2);
    return w;
}
//@endif

// The point that receives the VPLs: the pixel's surface, the rough end of its specular chain, or a
// row of the reduced matrix.
struct Receiver {
    vec3 p;
    vec3 n;   // shading normal, on the side the point is shaded from
    vec3 ng;  // geometric normal, on the same side
    vec3 wo;  // towards the camera, or back along the chain
    Closure closure;
    vec3 weight;          // the chain's throughput (1 without one)
    uint max_vpl_length;  // the longest VPL path the chain's end may receive
};

// Defined by the including stage after this file: whether VPL v and the receiver see each other,
// 1 or 0, from map i (the VPL's cube in the shading pass, the row's in the reduced matrix;
// to_receiver = r.p − v.position, d = |to_receiver|, res: the cubes' side).
float local_visibility(uint i, GpuVpl v, Receiver r, vec3 to_receiver, float d, float res);
//@if directional
float directional_vpl_visibility(uint i, GpuVpl v, Receiver r);
//@endif

//@if directional
// light::vpl_contribution of directional VPL i (a distant light or the environment's), added to
// sum.
void add_directional_vpl(uint i, GpuVpl v, Receiver r, inout vec3 sum) {
    const vec3 to_light = -v.normal;
    const float cos_r = max(0.0, dot(r.n, to_light));
    // light::vpl_contribution: light from below the geometric surface never reaches it, though a
    // bump- or normal-mapped n may face it.
    if (cos_r <= 0.0 || !(dot(r.ng, to_light) > 0.0)) return;
    const vec3 f_r = closure_eval(r.closure, r.n, r.wo, to_light);
    if (max_component(f_r) <= 0.0) return;
    const float vis = (pc.flags & kShadows) != 0u ? directional_vpl_visibility(i, v, r) : 1.0;
    sum += vpl_pair(v.power * vis, f_r, cos_r, VplFactors(1.0, vec3(1.0), vec3(1.0)), 1.0, 0.0);
}
//@endif

//@if point|spot|area|surface
// A VPL's own factors towards w, VPL → receiver (shared/vpl_pair.h); f widened by spread2.
VplFactors vpl_factors(GpuVpl v, vec3 w, float spread2, bool by_lobe) {
    VplFactors e = VplFactors(1.0, vec3(1.0), vec3(1.0));
//@if spot
    if (v.type == kVplSpot) e.emitter = spot_falloff(v.cos_inner, v.cos_outer, dot(v.normal, w));
//@endif
//@if area|surface
    if (v.type == kVplArea || v.type == kVplSurface) e.emitter = max(0.0, dot(v.normal, w));
//@endif
//@if surface
    if (v.type == kVplSurface) {
        const Closure c = Closure(v.closure_type, v.base_color, v.metallic, v.specular_color,
                                  v.specular, v.roughness, v.ior);
//@if glossy
        e.f = closure_eval(spread2 > 0.0 && c.type != 0u ? widen_closure(c, spread2) : c,
                           v.shading_normal, v.wi, w);
        if (by_lobe) e.f_diffuse = closure_eval_diffuse(c, v.shading_normal, v.wi, w);
//@endif
//@if !glossy
        e.f = closure_eval(c, v.shading_normal, v.wi, w);
//@endif
    }
//@endif
    return e;
}

// light::vpl_contribution of VPL i at a point (point, spot, area or surface), added to sum.
void add_local_vpl(uint i, GpuVpl v, Receiver r, float shadow_res, inout vec3 sum) {
    const vec3 to_receiver = r.p - v.position;
    const float d2 = dot(to_receiver, to_receiver);
    if (!(d2 > 0.0)) return;
    const float d = sqrt(d2);
    const vec3 w = to_receiver / d;  // VPL → receiver
    const float cos_r = max(0.0, dot(r.n, -w));
    // As for directional VPLs: none from below the geometric surface, whatever n says.
    if (cos_r <= 0.0 || !(dot(r.ng, -w) > 0.0)) return;
    float spread2 = 0.0;
    bool by_lobe = false;
//@if glossy
    // Area and surface VPLs are virtual spherical lights: both lobes widened (light::
    // vpl_contribution; shared/virtual_sphere.h).
    spread2 = v.type == kVplArea || v.type == kVplSurface ? vsl_spread2(pc.vsl_r2, d2) : 0.0;
    // A pair with a widened glossy lobe in it is clamped lobe by lobe (light::vpl_contribution;
    // shared::vsl_glossy_d2): f_vpl's diffuse lobe alone, an area VPL's emission counting as
    // diffuse.
    by_lobe = clamps_by_lobe(spread2, pc.d_min2,
                             r.closure.type != 0u ||
                                 (v.type == kVplSurface && v.closure_type != 0u));
//@endif
    const VplFactors e = vpl_factors(v, w, spread2, by_lobe);
    if (e.emitter <= 0.0 || max_component(e.f) <= 0.0) return;
//@if glossy
    const vec3 f_r =
        closure_eval(spread2 > 0.0 && r.closure.type != 0u ? widen_closure(r.closure, spread2)
                                                           : r.closure,
                     r.n, r.wo, -w);
//@endif
//@if !glossy
    const vec3 f_r = closure_eval(r.closure, r.n, r.wo, -w);
//@endif
    if (max_component(f_r) <= 0.0) return;
    const float vis = (pc.flags & kShadows) != 0u
                          ? local_visibility(i, v, r, to_receiver, d, shadow_res)
                          : 1.0;
//@if glossy
    if (by_lobe) {
        sum += vpl_pair_by_lobe(v.power * vis, f_r, closure_eval_diffuse(r.closure, r.n, r.wo, -w),
                                cos_r, e, d2, pc.vsl_r2, pc.d_min2);
        return;
    }
//@endif
    sum += vpl_pair(v.power * vis, f_r, cos_r, e, d2, pc.d_min2);
}
//@endif
