#pragma once
// The CPU VPL gather: the oracle for the GPU renderer (DESIGN.md "Reference and oracle"). It
// shades the same VPL list with the contribution formulas of engine/light/vpl.h and exact Embree
// visibility, so that a difference from the GPU image is a shadow-map or shader error, never a
// sampler error.
//
// One camera ray per pixel through the pixel centre (the G-buffer rasterises pixel centres). At
// its first hit: the emitted radiance seen directly (front face only, when max_depth ≥ 1 or
// unlimited) plus the VplSet's scale times the sum over VPLs of their contributions, with
// d_min = clamp · (diagonal of the scene's bounding box); clamp 0 turns clamping off.
#include <optional>
#include <vector>

#include "engine/core/image.h"
#include "engine/light/vpl.h"
#include "engine/material/bsdf.h"
#include "engine/reference/shading_point.h"
#include "engine/scene/scene.h"
#include "engine/trace/accel.h"
#include "engine/trace/ray.h"

namespace mvpl::reference {

// The per-point pieces of the gather, shared with the Metropolis sampler's importance
// (sampler/importance.h), so that its target uses exactly the oracle's contribution formula.

// What is fixed per VPL, prepared once rather than per receiver.
struct PreparedVpl {
    const light::Vpl* vpl = nullptr;
    std::optional<material::Bsdf> bsdf;  // Surface only
    Frame frame;                         // Surface only: around the VPL's shading normal
    Vec3 wi_local{0.0f, 0.0f, 1.0f};     // Surface only
};
PreparedVpl prepare_vpl(const light::Vpl& vpl);

// A camera ray's first hit made ready to receive VPL light.
struct Receiver {
    ShadingPoint sp;
    Vec3 wo{0.0f, 0.0f, 1.0f};  // towards the camera, in sp.frame; wo.z > 0
};
// The receiver at the first hit of `camera_ray`, if any and seen from above its shading surface;
// `emitted` (optional) receives the emitted radiance seen there (front face only).
std::optional<Receiver> make_receiver(const scene::Scene& scene, const trace::Accel& accel,
                                      const trace::Ray& camera_ray, Rgb* emitted = nullptr);

// One VPL's contribution to one receiver (vpl.h), Embree visibility included; d_min2 = d_min².
Rgb vpl_contribution(const trace::Accel& accel, const Receiver& receiver, const PreparedVpl& pv,
                     float d_min2);

struct GatherOptions {
    int width = 256;
    int height = 256;
    float clamp = light::kDefaultClamp;  // d_min as a fraction of the scene's diagonal
    // Mitsuba's max_depth; it only decides whether emitters seen directly are shown (≥ 1 or < 0).
    // Which VPLs exist for that depth is the sampler's business (LightTracer).
    int max_depth = 6;
    bool quiet = true;
};

struct GatherStats {
    double seconds = 0.0;
    uint64_t rays = 0;  // camera and shadow rays
};

// Deterministic, whatever the thread count.
Image gather_vpls(const scene::Scene& scene, const trace::Accel& accel, const light::VplSet& vpls,
                  const GatherOptions& options, GatherStats* stats = nullptr);

}  // namespace mvpl::reference
