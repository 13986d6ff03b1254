#pragma once
// What one camera ray reports to the AOVs (aov_kind.h): the first surface it meets, or, where that
// surface continues a specular chain (light/specular_chain.h), the rough surface at the chain's
// end, which is what the VPLs light in that pixel. Traced on the CPU with Embree and the C++
// material evaluators, the code the GPU renderer's own chain layer and the oracle run, so the
// chains are the image's own: the same generator (light::chain_rng) gives the same paths.
//
// Why not the GPU's G-buffer, which holds base colour, normal and position per sub-pixel position
// already: the chained pixels' rough ends live in the chain layer, not in it; the G-buffers of a
// render are spread over devices and MPI ranks; the oracle and the reference have none. The CPU
// gives the same AOVs for all of them at a cost measured in README, "AOVs".
#include <memory>
#include <optional>

#include "engine/core/color.h"
#include "engine/core/math.h"
#include "engine/core/rng.h"
#include "engine/light/chain_options.h"
#include "engine/light/light_sampler.h"
#include "engine/scene/scene.h"
#include "engine/trace/accel.h"

namespace mvpl::aov {

// One ray's values; all zero where it meets nothing (the environment) or its chain ends nowhere
// rough, so that a pixel's mean is the coverage mix (Mitsuba's aov integrator writes 0 too).
struct AovSample {
    Rgb albedo{0.0f};
    Vec3 normal{0.0f};
    Vec3 position{0.0f};
    float depth = 0.0f;  // the path's length from the eye to the reported surface
};

class AovTracer {
public:
    // chains: the render's (RenderOptions::chains); disabled: every pixel its first surface.
    AovTracer(const scene::Scene& scene, const trace::Accel& accel, const scene::Camera& camera,
              int width, int height, const light::ChainOptions& chains);
    ~AovTracer();

    // The ray through film point `film` (pixels, scene::generate_camera_ray); `chain` draws the
    // chain's samples (light::chain_rng of the pixel and position).
    AovSample sample(const Vec2& film, Rng& chain) const;

private:
    const scene::Scene& m_scene;
    const trace::Accel& m_accel;
    const scene::Camera& m_camera;
    int m_width;
    int m_height;
    light::ChainOptions m_chains;  // disabled where the scene has nothing to continue
    // The chains' light sampler, as the chain layer builds it: its light samples draw from the
    // same generator, so the BSDF samples after them are the image's.
    std::unique_ptr<light::LightSampler> m_lights;
};

}  // namespace mvpl::aov
