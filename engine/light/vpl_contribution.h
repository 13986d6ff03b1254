#pragma once
// One VPL's contribution to one receiver (the formulas of vpl.h, Embree visibility): the one
// implementation that the CPU oracle (reference::gather_vpls) and the Metropolis sampler's target
// (engine/sampler/importance.h) share, so that the target sees exactly what the oracle shades.
#include <optional>

#include "engine/core/color.h"
#include "engine/core/math.h"
#include "engine/light/vpl.h"
#include "engine/material/bsdf.h"
#include "engine/scene/scene.h"
#include "engine/trace/accel.h"
#include "engine/trace/ray.h"
#include "engine/trace/shading_point.h"

namespace mvpl::light {

// What is fixed per VPL, prepared once rather than per receiver.
struct PreparedVpl {
    const Vpl* vpl = nullptr;
    std::optional<material::Bsdf> bsdf;  // Surface only
    Frame frame;                         // Surface only: around the VPL's shading normal
    Vec3 wi_local{0.0f, 0.0f, 1.0f};     // Surface only
};
PreparedVpl prepare_vpl(const Vpl& vpl);

// A camera ray's first hit made ready to receive VPL light.
struct Receiver {
    trace::ShadingPoint sp;
    Vec3 wo{0.0f, 0.0f, 1.0f};  // towards the camera, in sp.frame; wo.z > 0
};
// The receiver at the first hit of `ray`, if any and seen from above its shading surface;
// `emitted` (optional) receives the emitted radiance seen there (front face only), or the
// environment's where the ray leaves the scene. A camera ray (`from_camera`) passes through the
// back faces of one-sided materials (Accel::intersect_camera); a ray continued from a surface
// (light/specular_chain.h) does not. `transmissive_back`: a transmissive surface seen from below
// is returned too (wo.z < 0), for the specular chains to continue through it.
// `emitter` (optional) receives where the emitted radiance was found on an emissive surface
// (mesh −1: on none, e.g. the environment), for weighting it against light sampling.
struct EmitterHit {
    int mesh = -1;
    int triangle = -1;
    Vec3 p{0.0f};
    Vec3 ng{0.0f};  // the front face's geometric normal
};
std::optional<Receiver> make_receiver(const scene::Scene& scene, const trace::Accel& accel,
                                      const trace::Ray& ray, Rgb* emitted = nullptr,
                                      bool from_camera = true, bool transmissive_back = false,
                                      EmitterHit* emitter = nullptr);

// One VPL's contribution to one receiver (vpl.h), Embree visibility included; d_min2 = d_min².
// vsl_r2 = r², the squared radius of the virtual spherical lights that area and surface VPLs
// become (virtual_sphere.h): their glossy lobes and the receiver's are integrated over the
// sphere, and a pair with a glossy lobe in it is clamped lobe by lobe (vpl.h); 0 shades point
// VPLs.
Rgb vpl_contribution(const trace::Accel& accel, const Receiver& receiver, const PreparedVpl& pv,
                     float d_min2, float vsl_r2 = 0.0f);
// The same without visibility, and the shadow ray that decides it: vpl_contribution is this
// where `shadow` is not occluded, black where it is. Black where the pair exchanges no light
// (then no ray is written and none need be traced), so that a caller can trace the rays of many
// pairs together (Accel::occluded over a span: the reduced matrix of manylights/).
// `coordinate_scale` is the Accel's, for the ray's offsets.
Rgb unshadowed_contribution(const Receiver& receiver, const PreparedVpl& pv, float d_min2,
                            float vsl_r2, float coordinate_scale, trace::Ray& shadow);

}  // namespace mvpl::light
