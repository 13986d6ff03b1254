#pragma once
// Where row-column sampling is on by default (`--pool auto`): the pool size a run gets when the
// user names none. At equal time it paid on diffuse interiors lit by their own lights and lost
// on glossy receivers and under the sky (docs/results.md, "Row-column sampling", "Clusters of
// bounded size"), idle machine, 256² / 128², relMSE per pixel / on 8×8 blocks against every VPL
// shaded, medians of three seeds or more:
//   Cornell box, Monte Carlo, N 16384: 1.53× / 4.0× below at 5 s, 1.54× / 3.5× at 15 s,
//   1.15× / 1.67× at 60 s;
//   two rooms, Monte Carlo, N 16384: 4.4× / 9.3× at 5 s, 7.1× / 13× at 15 s (seeds 1–6);
//   Metropolis, N 16384: the Cornell box 1.7× / 2.1× and the two rooms 1.4× / 2.1× at 15 s, the
//   two rooms 0.9× / 1.35× at 5 s (a Metropolis render's first pools are few);
//   DamagedHelmet, MetalRoughSpheresNoTextures under the sky (metal receivers), N 8192:
//   0.6–0.7× per pixel at 15 s: each VPL's highlight on a metal becomes a representative's spot.
// Below about 2 s a render's few short pools made it worse than every VPL shaded, and on an H200
// (Cornell box, with the CPU's matrix) it read 0.72× / 0.59× at 5 s: it is measured to pay on a
// CPU implementation of Vulkan (lavapipe) only.
#include <cstdint>
#include <string_view>

#include "engine/scene/scene.h"

namespace mvpl::manylights {

// The pool `auto` picks where it pays.
inline constexpr uint32_t kAutomaticPool = 16384;
// The shortest time budget `auto` turns it on for, in seconds: Monte Carlo and Metropolis VPLs.
inline constexpr double kAutomaticMinSeconds = 5.0;
inline constexpr double kAutomaticMinSecondsMetropolis = 15.0;

// Whether every material the scene draws reflects diffusely (no metal, specular layer,
// transmission or specular-glossiness model) and no environment lights it.
bool diffuse_interior(const scene::Scene& scene);

// The pool for `auto`: kAutomaticPool for a render of at least kAutomaticMinSeconds (Monte Carlo,
// `sampler` "mc") or kAutomaticMinSecondsMetropolis (`time_budget`, 0 for a fixed VPL count) of a
// diffuse interior on a CPU implementation of Vulkan (`cpu_device`), else 0 (every VPL shaded).
uint32_t automatic_pool(const scene::Scene& scene, std::string_view sampler, double time_budget,
                        bool cpu_device);

}  // namespace mvpl::manylights
