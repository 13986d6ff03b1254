#pragma once
// How the VPL image, the specular chains and the caustic tracer share path space (issue 15), so
// that their sum counts every path once. A camera-to-light path y_0 (the eye), y_1 (the first
// hit), …, y_n (on a light); two tests classify its vertices:
//
//   chain(y_i):  continues_chain(bsdf, ω towards y_{i−1}) — the camera path is continued there
//                (light/specular_chain.h);
//   vpl(y_j):    leaves_vpl(bsdf, ω towards y_{j+1}) — the light path leaves a VPL there, which
//                reflects light (its closure keeps no transmission: engine/sampler/light_tracer.h).
//
// VPLs + chains: chain(y_1…y_{m−1}), not chain(y_m), y_m seen from above (the receiver), and
//   y_{m+1} the light or a vpl vertex that reflects towards y_m (towards the side it was lit on).
// Caustic tracer (integrator/caustic_tracer.h): not chain(y_1), y_1 seen from above, and y_2 a
//   surface vertex that is not vpl or that transmits towards y_1 — exactly the paths with a
//   receiver at y_1 that the first estimator misses.
// Neither: chain(y_1) and y_{m+1} a surface vertex that is not vpl or transmits (a caustic seen
//   in a mirror or through glass). A light tracer cannot connect through a specular y_1 to the
//   eye; those paths are left out (their light is lost, as before this partition).
//
// `specular` is the chains' ChainOptions when the caustic tracer runs; disabled (max_roughness
// < 0), every front vertex leaves a VPL and only transmission and back sides go to the caustics.
//
// Which of the two a path takes is decided per path, by its emitter (path_chain_class): a path
// from the environment leaves a VPL at every front vertex, near-mirrors included, so that the
// caustic tracer takes only its light through transmission and back sides. Light tracing from an
// environment starts on a disc over the whole scene, and its splats off near-mirrors onto glossy
// receivers (f towards the camera up to tens per steradian) came out as isolated pixels 20–50×
// the reference: at 15 s DamagedHelmet and MetalRoughSpheresNoTextures under the default sky had
// per-pixel relMSE 1.1–4.5× above that of near-mirror VPLs (docs/results.md, "Caustics"). Each
// path is counted by one estimator whichever class it takes, so the sum stays unbiased.
#include "engine/light/chain_options.h"
#include "engine/light/light_sampler.h"
#include "engine/material/bsdf.h"
#include "engine/scene/scene.h"

namespace mvpl::light {

// Whether a light-path vertex lit from wi (local, towards the previous vertex) leaves a VPL: lit
// on its shading side (the GPU cannot tell a transmissive surface's sides apart) and not of the
// chains' class (continues_chain, the same test the chains make towards the camera).
bool leaves_vpl(const material::Bsdf& bsdf, const Vec3& wi, const ChainOptions& specular);

// The chains' class that leaves_vpl applies on a light path from `emitter`: `specular`, or none
// (disabled) on a path from the environment (header comment).
ChainOptions path_chain_class(const ChainOptions& specular, EmitterType emitter);

// Whether some drawn material can make a vertex whose light no VPL carries: one that transmits
// (not fully metallic, with a transmission factor or texture), or one the chains may continue
// (scene_may_chain) lit by an emitter other than the environment (path_chain_class). A scene
// without either (diffuse only, or near-mirrors under a sky alone) needs no caustic tracer.
bool scene_may_need_caustics(const scene::Scene& scene, const ChainOptions& specular,
                             const LightSampler& lights);

}  // namespace mvpl::light
