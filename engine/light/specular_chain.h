#pragma once
// Camera paths continued through glossy surfaces (issue 15; the "final gather through specular
// surfaces" of Keller's instant radiosity and of Hašan et al.'s VSL paper, §6): a point VPL
// lights a near-mirror only where its one direction lands in the narrow lobe, so a glossy
// pixel is black with sparkles at any VPL count users run. Instead, the camera path is continued
// by sampling the glossy surface's BSDF (one sample per pixel and sub-pixel position, so that the
// batches of a render average over many) until it reaches a rough surface, which the VPLs light
// as they light any pixel, weighted by the path's throughput. Emitted light the chain meets on
// the way (emitters, the environment where it leaves the scene) is added as seen.
//
// Unbiased as a one-sample estimate of the glossy surface's reflection integral: L(x₀ → eye) =
// Le(x₀) + f·cos/pdf · L(x₁ → x₀) with L at x₁ what the VPLs (plus Le(x₁)) give there.
//
// Path lengths keep Mitsuba's max_depth: a receiver reached after `bounces` glossy vertices is
// the (bounces + 1)-th vertex of the camera path, and a VPL whose light travelled
// path_length segments lights it through a path of bounces + 2 + path_length segments.
#include <cstdint>
#include <optional>

#include "engine/core/color.h"
#include "engine/core/rng.h"
#include "engine/light/chain_options.h"
#include "engine/light/vpl_contribution.h"
#include "engine/material/bsdf.h"
#include "engine/material/closure.h"
#include "engine/scene/scene.h"
#include "engine/trace/accel.h"
#include "engine/trace/ray.h"

namespace mvpl::light {

class LightSampler;

// Whether a surface with this BSDF, seen from wo (local), is continued rather than lit by VPLs:
// one whose transmission carries at least half of what it scatters (KHR_materials_transmission:
// VPLs cannot light through a surface), whatever its roughness; otherwise smooth enough, and its
// specular lobe carries at least half of what it reflects towards wo
// (Bsdf::specular_probability). A glossy coat over a diffuse base (a plastic) mostly is not:
// sampling its whole BSDF would light the base through one chain sample per sub-pixel position
// instead of through every VPL (measured on assets/glossy: speckled plastics at 256 VPLs), so it
// keeps VPL light but near grazing, where its Fresnel reflection dominates.
bool continues_chain(const material::Bsdf& bsdf, const Vec3& wo, const ChainOptions& options);
// Whether some drawn material of the scene may be continued: a specular lobe (metallic or
// specular factor above 0) and a roughness factor at most the bound, or a roughness texture; or
// a transmission factor or texture (not fully metallic).
bool scene_may_chain(const scene::Scene& scene, const ChainOptions& options);

struct ChainedReceiver {
    std::optional<Receiver> receiver;  // the first rough vertex; none: nothing to light
    Rgb throughput{1.0f};              // camera path weight up to the receiver
    uint32_t bounces = 0;              // glossy vertices before the receiver
    bool continued = false;            // the first vertex was glossy: the chain replaces it
    // The longest VPL path (segments) that may light the receiver under max_depth; UINT32_MAX
    // when unlimited.
    uint32_t max_vpl_length = UINT32_MAX;
    // The length of the path from the camera ray's origin to the receiver, segment by segment
    // (where a mirror shows the receiver to be: the depth AOV of engine/aov).
    float distance = 0.0f;
    // Emitted radiance met after the first vertex (emitters, the environment), and the punctual
    // lights' radiance reflected at each glossy vertex (a BSDF sample never finds a delta light),
    // weighted by the throughput to it; the first vertex's own emission goes to
    // make_chained_receiver's `emitted`.
    Rgb chain_emitted{0.0f};
};

// make_receiver, continued through glossy vertices with `rng`'s samples; `emitted` (optional)
// receives the emitted radiance seen along the chain, weighted by its throughput. `lights`
// (optional): the scene's light sampler, for one light sample per glossy vertex towards the
// emitters a BSDF sample can find too (area lights, the environment), both weighted by the power
// heuristic; without it they are found by the BSDF samples alone (unbiased, noisier for small
// emitters in sharp lobes). The GPU renderer's chain layer and the oracle pass the same.
ChainedReceiver make_chained_receiver(const scene::Scene& scene, const trace::Accel& accel,
                                      const trace::Ray& camera_ray, Rng& rng,
                                      const ChainOptions& options, Rgb* emitted = nullptr,
                                      const LightSampler* lights = nullptr);

// The light the chains of pixel (x, y) of a width × height view through `camera` meet at one
// sub-pixel position: `first`'s (the position's own chain) where options.emission_samples ≤ 1
// or the pixel's centre is not continued (pixel_centre_continues, which the caller evaluates
// once per pixel and view), else the mean of it and emission_samples − 1 chains through uniform
// random points of the pixel drawn from `rng`. Each is unbiased, and whether they are drawn does
// not depend on them.
bool pixel_centre_continues(const scene::Scene& scene, const trace::Accel& accel,
                            const scene::Camera& camera, int width, int height, int x, int y,
                            const ChainOptions& options);
Rgb pixel_chain_emission(const scene::Scene& scene, const trace::Accel& accel,
                         const scene::Camera& camera, int width, int height, int x, int y,
                         bool centre_continues, const ChainedReceiver& first, Rng& rng,
                         const ChainOptions& options, const LightSampler* lights);

// The generator of a pixel's chain at one sub-pixel position: the same on the CPU oracle and
// for the GPU renderer's chain layer, so both follow the same paths.
inline Rng chain_rng(uint64_t seed, uint64_t pixel, uint64_t position) {
    return Rng(mix_bits(seed ^ mix_bits(pixel + 1)), position);
}

}  // namespace mvpl::light
