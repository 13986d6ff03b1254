#pragma once
// The CPU VPL gather: the oracle for the GPU renderer (docs/design.md "Reference and oracle"). It
// shades the same VPL list with light::vpl_contribution (engine/light/vpl_contribution.h, the
// formulas of vpl.h) and exact Embree visibility, so that a difference from the GPU image is a
// shadow-map or shader error, never a sampler error.
//
// One camera ray per pixel and sub-pixel position, the positions the GPU renderer's G-buffers
// take for the same VPLs (engine/core/subpixel.h, render::VplRenderer). At its first hit: the
// emitted radiance seen directly (front face only, when max_depth ≥ 1 or unlimited) plus the
// VplSet's scale times the sum over the VPLs at that position of their contributions, with
// d_min = clamp · (diagonal of the scene's bounding box); clamp 0 turns clamping off.
#include <cstdint>
#include <vector>

#include "engine/core/image_size.h"
#include "engine/core/subpixel.h"
#include "engine/light/path_depth.h"

#include "engine/core/image.h"
#include "engine/light/specular_chain.h"
#include "engine/light/virtual_sphere.h"
#include "engine/light/vpl.h"
#include "engine/scene/scene.h"
#include "engine/trace/accel.h"

namespace mvpl::reference {

struct GatherOptions {
    int width = int(kDefaultImageWidth);
    int height = int(kDefaultImageHeight);
    float clamp = light::kDefaultClamp;  // d_min as a fraction of the scene's diagonal
    // Radius of the virtual spherical lights, a fraction of the scene's diagonal, as
    // RenderOptions::vsl_radius (light/virtual_sphere.h); 0: point VPLs.
    float vsl_radius = light::kDefaultVslRadius;
    // Mitsuba's max_depth; it only decides whether emitters seen directly are shown (≥ 1 or < 0).
    // Which VPLs exist for that depth is the sampler's business (LightTracer).
    int max_depth = light::kDefaultMaxDepth;
    bool quiet = true;
    // VPL i of the list is shaded at sub-pixel position subpixel.position_of(first_vpl + i), as
    // VplRenderer shades it after first_vpl others since begin() (a chunk of a progressive
    // render); the emitted radiance seen directly is the mean over the positions 0 …
    // subpixel.positions_after(first_vpl + list size) − 1, the G-buffers the renderer has drawn by
    // then. The default schedule is RenderOptions' (batch 32, jitter on).
    SubpixelSchedule subpixel;
    uint64_t first_vpl = 0;
    // Camera paths continued through glossy surfaces (light/specular_chain.h), one chain per
    // pixel and sub-pixel position drawn from light::chain_rng(chain_seed, pixel, position);
    // max_roughness < 0 (the default): none. The emitted radiance a chain meets counts as seen
    // directly (averaged over the same positions).
    light::ChainOptions chains;
    uint64_t chain_seed = 0;
    // Interleaved sampling as RenderOptions::interleave does it (interleaved_gather.h): 1 for
    // none.
    int interleave = 1;
};

struct GatherStats {
    double seconds = 0.0;
    uint64_t rays = 0;  // camera and shadow rays
};

// Deterministic, whatever the thread count.
Image gather_vpls(const scene::Scene& scene, const trace::Accel& accel, const light::VplSet& vpls,
                  const GatherOptions& options, GatherStats* stats = nullptr);

}  // namespace mvpl::reference
