#pragma once
// Light paths traced on Embree from primary samples, leaving virtual point lights
// (docs/design.md "The algorithm"; Keller 1997, Segovia et al. 2007).
//
// A path x_0 (on a light), x_1, …, x_k leaves an emitter VPL at x_0 (path_length 0: direct light)
// and a surface VPL at every x_j, j ≥ 1 that path_partition.h's leaves_vpl keeps (not a vertex lit
// from behind, nor one of the chains' class while the caustic tracer runs). The VPL's power is
// the path throughput at x_j (not divided by the number of light paths: vpl.h):
//   β_0 = Le·|cos θ_0| / (pick · pdf_pos · pdf_dir)                 (LightSampler::sample_le)
//   β_j = β_{j−1} · f_{j−1} · |n_g,{j−1}·ω_out| / pdf  ·  |n_s,j·ω_in| / |n_g,j·ω_in|
// The cosines at x_{j−1} towards x_j are geometric and the cosine at x_j towards x_{j−1} is the
// shading one: the path tracer's integrand read from the light's end (it uses the shading cosine
// towards the light and the area-measure change uses the geometric one), and the vpl.h formula
// uses the geometric max(0, n_j·ω) at the VPL — so the VPL estimator and the path tracer agree
// with shading normals too (the same factor as pbrt-v3's adjoint shading-normal correction).
//
// Depth: a VPL with path_length k lights a camera-visible point through a camera-to-light path of
// k + 2 segments (Mitsuba's max_depth), so only k ≤ max_depth − 2 is kept; max_depth < 0 is
// unlimited and Russian roulette ends the paths.
#include <cstdint>
#include <vector>

#include "engine/light/chain_options.h"
#include "engine/light/light_sampler.h"
#include "engine/light/path_depth.h"
#include "engine/light/vpl.h"
#include "engine/sampler/sample_stream.h"
#include "engine/scene/scene.h"
#include "engine/trace/accel.h"

namespace mvpl::sampler {

struct LightTracerOptions {
    int max_depth = light::kDefaultMaxDepth;  // light/path_depth.h; < 0 unlimited
    // Russian roulette once the camera-to-light path through the next VPL would have at least
    // this many segments (the path tracer's rr_depth, counted the same way).
    int rr_depth = light::kDefaultRrDepth;
    // With the caustic tracer (integrator/caustic_tracer.h): vertices of the chains' class leave
    // no VPL (light/path_partition.h, leaves_vpl), the caustic tracer carries their light —
    // except on paths from the environment (path_chain_class). Disabled (the default): a VPL on
    // every vertex lit on its shading side.
    light::ChainOptions specular;
};

class LightTracer {
public:
    LightTracer(const scene::Scene& scene, const trace::Accel& accel,
                const light::LightSampler& lights, const LightTracerOptions& options = {});

    // Traces one light path from `u` and appends its VPLs in path order (emitter VPL first).
    // Returns the number of VPLs appended.
    size_t trace(SampleStream& u, std::vector<light::Vpl>& out) const;
    // The emitter VPL alone (path_length 0) from the emission dimensions of `u` (the same ones
    // trace() reads first, so the same u gives the same VPL), without tracing the path; nothing
    // when the sample misses or max_depth leaves no VPL. Returns the number appended (0 or 1).
    size_t trace_emitter(SampleStream& u, std::vector<light::Vpl>& out) const;

    // Largest path_length a VPL may have for the options' max_depth (−1: none at all).
    int max_path_length() const;
    const LightTracerOptions& options() const { return m_options; }

private:
    light::Vpl emitter_vpl(const light::EmissionSample& es) const;

    const scene::Scene& m_scene;
    const trace::Accel& m_accel;
    const light::LightSampler& m_lights;
    LightTracerOptions m_options;
};

}  // namespace mvpl::sampler
