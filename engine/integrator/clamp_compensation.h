#pragma once
// Clamping compensation (Kollig & Keller 2004, "Illumination in the presence of weak
// singularities"): the energy that the clamped geometric term of the VPL estimate removes,
// recovered on the CPU by BSDF sampling from each receiver.
//
// The VPL estimate divides by max(d², d_min²) instead of d² (docs/design.md, "The algorithm"), so a
// surface point y at distance d < d_min from the receiver x contributes only the fraction d²/d_min²
// of its light. The rest is
//
//     C(x) = ∫ f(x, ω, ωo) L(y(ω) → x) cos θ · max(0, 1 − d(ω)²/d_min²) dω,
//
// which one BSDF sample estimates as (f cos θ / pdf) · L(y → x) · max(0, 1 − d²/d_min²), with
// L(y → x) the radiance the path tracer finds along the sampled ray (reference::PathTracer, the
// path's remaining depth; emission at y included). A ray is bounded by d_min, so a sample that
// finds nothing nearer costs one short ray. Point and spot lights nearer than d_min, which no BSDF
// sample can hit, are compensated by evaluating them: I · (1/d² − 1/d_min²) with exact visibility.
// Clamped VPL image + C is unbiased, whatever the clamp (tests/integrator/test_clamp_compensation).
//
// With virtual spherical lights (vsl_radius > 0) the VPL estimate clamps lobe by lobe
// (light/vpl_contribution.h): only the product of the receiver's diffuse lobe f_D and the VPL's
// diffuse lobe (or an emitter VPL's emission) keeps max(d², d_min²). C then adds back that
// product's share alone,
//
//     C(x) = ∫ f_D(x, ω, ωo) L_D(y(ω) → x) cos θ · max(0, 1 − d(ω)²/d_min²) dω,
//
// L_D the radiance leaving y through its diffuse lobe, plus its emission (PathTracer with
// FirstVertex::DiffuseLobe), sampled from f_D's cosine density: the glossy products, which the
// estimate no longer clamps at d_min, would otherwise be counted twice. Punctual lights keep the
// full clamp, and their part stays as above. A Lambertian scene gets the same numbers either
// way (Bsdf::sample_diffuse).
#include <cstdint>
#include <memory>

#include "engine/core/image.h"
#include "engine/core/image_size.h"
#include "engine/light/chain_options.h"
#include "engine/light/light_sampler.h"
#include "engine/light/path_depth.h"
#include "engine/light/virtual_sphere.h"
#include "engine/light/vpl.h"
#include "engine/scene/scene.h"
#include "engine/trace/accel.h"

namespace mvpl::integrator {

struct CompensationOptions {
    int width = int(kDefaultImageWidth);
    int height = int(kDefaultImageHeight);
    float clamp = light::kDefaultClamp;  // d_min as a fraction of the scene's diagonal
    // The VPL image's virtual spherical lights (scene diagonals, light/virtual_sphere.h); 0
    // (--no-vsl): the whole BSDF is clamped and compensated.
    float vsl_radius = light::kDefaultVslRadius;
    int max_depth = light::kDefaultMaxDepth;  // of the whole path, camera included; < 0: unlimited
    int rr_depth = light::kDefaultRrDepth;
    // The renderer's specular chains (light/specular_chain.h): a pixel they continue is
    // compensated at the rough end of its chain, weighted by its throughput, where the VPLs light
    // it, and not at its glossy first vertex, whose reflection the chain carries all of.
    light::ChainOptions chains;
    uint64_t seed = 0;
    // The camera whose pixels are compensated (copied); null: the scene's.
    const scene::Camera* camera = nullptr;
    // Pass i of this object is pass first_pass + i · pass_stride of the sequence the seed defines:
    // ranks of a cluster run every R-th pass from their rank, so that together they run one
    // process's passes.
    uint32_t first_pass = 0;
    uint32_t pass_stride = 1;
};

class ClampCompensation {
public:
    ClampCompensation(const scene::Scene& scene, const trace::Accel& accel,
                      const light::LightSampler& lights, const CompensationOptions& options);
    ~ClampCompensation();
    ClampCompensation(const ClampCompensation&) = delete;
    ClampCompensation& operator=(const ClampCompensation&) = delete;

    // One sample per pixel at a random sub-pixel position (a box filter, as the GPU's jittered
    // G-buffers), in parallel over rows; pass k is the same whatever the thread count. One thread
    // at a time adds passes; passes() and image() may be called from another meanwhile.
    void add_pass();
    uint32_t passes() const;
    // The mean over the passes completed so far (black before the first); `passes`, if given,
    // receives their count, read with the same lock (ranks weight their means by it).
    Image image(uint32_t* passes = nullptr) const;
    // Whether there is anything to compensate (clamping on and paths long enough for VPL light).
    bool active() const;

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

}  // namespace mvpl::integrator
