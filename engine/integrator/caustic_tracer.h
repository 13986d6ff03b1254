#pragma once
// Caustics: the light that reaches a rough surface the camera sees through a vertex that leaves no
// VPL — through glass (VPLs reflect only; shadow maps and the oracle's visibility treat glass as
// opaque), off the back of a transmissive surface, or off a near-mirror of the chains' class —
// found by light tracing (every light-path vertex connected to the eye: bidirectional path
// tracing's t = 1 strategy, Veach 1997 ch. 10; pbrt-v3 §16.1.1 for the pinhole's importance) and
// splatted into the pixel it projects to. Which paths it takes is light/path_partition.h:
// a light-path vertex x_j (j ≥ 2) whose previous vertex x_{j−1} was not a VPL that reflects
// towards x_j (on a path from the environment only transmission and back sides leave none:
// path_chain_class), and which the camera sees directly as a receiver (not of the chains' class,
// seen from above its shading surface). VPL image + chains + this image is then unbiased but for
// the caustics seen through a chain (path_partition.h, "Neither").
//
// Estimate of pixel P from N light paths (β_j the throughput at x_j, as a VPL's power there:
// engine/sampler/light_tracer.h):
//     I_P = (1/N) Σ β_j · f(ω_cam, ω_in) · |n_g·ω_cam| / d² · W_e(ω_cam) · V · [x_j projects into
//     P]
// with the pinhole's importance for a box-filtered pixel of image-plane area A_pix (at distance
// 1 from the eye): a pixel's camera rays are uniform over its area, so their solid-angle density
// is p(ω) = 1/(A_pix cos³θ) (the plane point at distance 1/cos θ, seen at cos θ), and the pixel's
// value ∫ L p dω becomes, with dω = |n_g·ω_cam| dA / d² at x_j, the importance
//     W_e = 1/(A_pix cos³θ),  A_pix = (2 tan(yfov/2))² · aspect / (width · height).
// The cosine at x_j towards the eye is the geometric one and β_j holds the shading one towards
// the light: the path tracer's integrand read from the light's end, as for VPLs. Visibility is
// the camera's own ray through the projected point (Accel::intersect_camera, from the near
// plane), which must find x_j.
//
// With clamping compensation (clamp_compensation.h) beside it, a vertex x_j nearer than d_min to
// x_{j−1} leaves the compensation its share: the compensation samples x_{j−1} from the receiver
// x_j and adds the share 1 − d²/d_min² of the light leaving it, this path included, although no
// VPL gave the clamped rest. The full compensation (point VPLs) takes that share of all of it, so
// the vertex is weighted by d²/d_min²; the lobe-wise one (virtual spherical lights:
// CompensationOptions::vsl_radius > 0) only of the product of the two diffuse lobes, f_D(x_j) at
// the receiver and f_D(x_{j−1}) at the vertex before, so the vertex keeps
// f(x_j) f(x_{j−1}) − (1 − d²/d_min²) f_D(x_j) f_D(x_{j−1}). Either way the two add to one.
//
// Which light a path starts from: global pass 0 (the pilot, whichever rank or object runs it)
// picks by power, as the VPLs' light paths, and measures each emitter's caustic light; every later
// pass picks with q_e = ½ p_power(e) + ½ C_e / Σ C (a defensive mixture: every emitter keeps half
// its power's share, so the estimate stays unbiased), since a light that reaches no glass
// otherwise spends its share of the paths on nothing (measured on assets/glass-pane: the point
// light drew 80 % of them). A rank that does not own pass 0 traces it too, unadded, so that pass k
// is the same on any number of ranks.
//
// Passes as in ClampCompensation: each traces `paths_per_pass` light paths (default one per
// pixel) and is deterministic for its seed whatever the thread count; image() is their mean.
#include <cstdint>
#include <memory>

#include "engine/core/image.h"
#include "engine/core/image_size.h"
#include "engine/light/chain_options.h"
#include "engine/light/light_sampler.h"
#include "engine/light/path_depth.h"
#include "engine/scene/scene.h"
#include "engine/trace/accel.h"

namespace mvpl::integrator {

struct CausticOptions {
    int width = int(kDefaultImageWidth);
    int height = int(kDefaultImageHeight);
    int max_depth = light::kDefaultMaxDepth;  // of the whole path, camera included; < 0: unlimited
    int rr_depth = light::kDefaultRrDepth;    // as sampler::LightTracerOptions::rr_depth
    // The chains' class (light/path_partition.h): the same options the renderer's chains and the
    // light tracer's `specular` use. Disabled: only transmission and back sides.
    light::ChainOptions specular;
    // The clamping compensation's d_min as a fraction of the scene's diagonal when it runs beside
    // (CompensationOptions::clamp), else 0.
    float clamp = 0.0f;
    // CompensationOptions::vsl_radius of that compensation: > 0 when it is lobe-wise.
    float vsl_radius = 0.0f;
    uint64_t seed = 0;
    uint64_t paths_per_pass = 0;  // 0: width × height
    // The camera whose pixels receive the caustics (copied); null: the scene's.
    const scene::Camera* camera = nullptr;
    // As CompensationOptions: pass i is pass first_pass + i · pass_stride of the seed's sequence.
    uint32_t first_pass = 0;
    uint32_t pass_stride = 1;
};

class CausticTracer {
public:
    CausticTracer(const scene::Scene& scene, const trace::Accel& accel,
                  const light::LightSampler& lights, const CausticOptions& options);
    ~CausticTracer();
    CausticTracer(const CausticTracer&) = delete;
    CausticTracer& operator=(const CausticTracer&) = delete;

    // Whether the scene has paths of its share: a light, a material that may leave no VPL on
    // their paths (scene_may_need_caustics) and max_depth ≥ 3 (light → x_1 → x_2 → eye). Inactive,
    // add_pass traces nothing.
    bool active() const;
    // One pass, in parallel; one thread at a time adds passes, passes() and image() may be called
    // from another meanwhile.
    void add_pass();
    uint32_t passes() const;
    // The mean over the passes completed so far (black before the first); `passes`, if given,
    // receives their count, read with the same lock.
    Image image(uint32_t* passes = nullptr) const;

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

}  // namespace mvpl::integrator
