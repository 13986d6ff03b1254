#pragma once
// The virtual point light record: what the sampler produces and the renderer and the CPU oracle
// consume (docs/design.md, "The algorithm"). The renderer knows this record, not how VPLs were
// chosen.
//
// Contribution of a VPL at x_j to a receiver x' (shading normal n', viewed from ω_o), with
// ω = unit(x' − x_j), d = |x' − x_j|, V the visibility and d_min the clamping distance:
//
//   Point:       power · V · f_r(ω_o, −ω) · cos θ'                          / max(d², d_min²)
//   Spot:        power · V · f_r(ω_o, −ω) · cos θ' · spot(axis·ω)           / max(d², d_min²)
//   Area:        power · V · f_r(ω_o, −ω) · cos θ' · max(0, n_j·ω)          / max(d², d_min²)
//   Surface:     power · V · f_r(ω_o, −ω) · cos θ' · f_j(ω_in, ω) · max(0, n_j·ω) / max(d², d_min²)
//   Directional: power · V · f_r(ω_o, −axis) · cos θ'            (V from an orthographic map)
//
// with cos θ' = max(0, n'·(−ω)), f_r the receiver's BRDF and f_j the VPL's own closure evaluated
// with its shading normal (seed eq. 5); 0 where −ω points below the receiver's geometric surface,
// whatever a bump or normal map makes n' face (light::vpl_contribution, the GPU's shading pass).
// For Area and Surface VPLs, virtual spherical lights of radius r (light/virtual_sphere.h; r = 0
// with --no-vsl): the GGX lobes of f_r and f_j are evaluated with α widened to
// √(α² + r²/(4 max(d², r²))), their integral over the sphere in closed form, and the clamp
// applies lobe by lobe (issue 15): with f_r = D_r + G_r and f_j = D_j + G_j split into diffuse
// and glossy lobes (Bsdf::eval_diffuse; an Area VPL's emission is diffuse, D_j = 1), only
// D_r·D_j keeps max(d², d_min²), and f_r·f_j − D_r·D_j, bounded by the widened lobes, is divided
// by max(d², min(r², d_min²)) (shared::vsl_glossy_d2). With r = 0 or d_min = 0 the formulas above
// hold as written. `power` holds the
// path throughput divided by all sampling densities, NOT by the number of light paths (or chain
// steps): that factor is the VplSet's `scale`, carried beside the VPLs, so that a sampler run
// progressively never needs to know its final length. An image is scale · Σ contributions (+ the
// emission seen directly, unscaled).
#include <cstdint>
#include <vector>

#include "engine/core/color.h"
#include "engine/core/math.h"
#include "engine/material/closure.h"

namespace mvpl::light {

enum class VplType : uint32_t { Point = 0, Spot = 1, Area = 2, Surface = 3, Directional = 4 };

// Default clamping distance d_min, as a fraction of the scene's bounding-box diagonal, for every
// image formed from VPLs (renderer, CPU oracle, Metropolis importance, preview, command line).
// Measured on the Cornell box (256 paths, 256², against Mitsuba): relMSE 0.039 unclamped, 0.015
// at 0.01, 0.0073 at 0.02, 0.0034 at 0.05, 0.0032 at 0.1, while the mean darkens by 0.5–1% at
// 0.05 and 1.5–2% at 0.1 — 0.05 removes nearly all of the singularity's noise for half the bias
// of 0.1. 0 turns clamping off (unbiased).
inline constexpr float kDefaultClamp = 0.05f;

struct Vpl {
    VplType type = VplType::Surface;
    Vec3 position{0.0f};
    // Area and Surface: geometric normal on the lit/emitting side. Spot: the axis (the way the
    // light travels). Directional: the direction of travel.
    Vec3 normal{0.0f, 0.0f, 1.0f};
    Vec3 shading_normal{0.0f, 0.0f, 1.0f};  // Surface only, on the same side as `normal`
    Vec3 wi{0.0f, 0.0f, 1.0f};  // Surface only: unit direction towards where its light came from
    Rgb power{0.0f};
    material::ClosureParams closure;  // Surface only
    float cos_inner = 1.0f;           // Spot only
    float cos_outer = 0.0f;           // Spot only
    uint32_t path_length = 0;         // segments from the light: 0 for emitter VPLs
};

// VPLs and the factor that turns the sum of their contributions into an estimate: 1/N for N
// Monte Carlo light paths, b/N for N Metropolis steps, 1 for hand-placed lights.
struct VplSet {
    std::vector<Vpl> vpls;
    double scale = 1.0;
};

}  // namespace mvpl::light
