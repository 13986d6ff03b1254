// What one VPL sends to one receiver once both ends' BSDFs are evaluated (engine/light/vpl.h),
// written once for C++ (engine/light/vpl_contribution.cpp: the CPU oracle and the Metropolis
// target) and GLSL (shaders/render/shading_template.glsl, after the closures, whose
// shading_constants.h defines MVPL_INLINE): the VPL's power through the receiver's f_r and cosine
// and the VPL's own factors, over the squared distance clamped at d_min (Kollig and Keller 2004);
// lobe_clamp.h clamps a virtual spherical light's pair lobe by lobe instead. Visibility is each
// side's own (an Embree ray on the CPU, the shadow cube's fraction on the GPU, which multiplies
// `power`). Common subset as in shading_math.h.
#ifndef MVPL_SHADERS_SHARED_VPL_PAIR_H
#define MVPL_SHADERS_SHARED_VPL_PAIR_H

#ifdef __cplusplus
#include <glm/glm.hpp>

#include "shaders/shared/shading_constants.h"

namespace mvpl::shared::math {
using vec3 = glm::vec3;
using glm::max;
#endif

// A VPL's own factors towards the receiver: `emitter`, the spot falloff or max(0, n_j·ω) (1 for a
// point or directional VPL); `f`, a surface VPL's BSDF f_j(ω_in, ω) (1 for the others), its
// lobes widened where the VPL is a sphere; `f_diffuse`, f_j's diffuse lobe alone, where the pair
// is clamped lobe by lobe (1 for an area VPL, whose emission counts as diffuse).
struct VplFactors {
    float emitter;
    vec3 f;
    vec3 f_diffuse;
};

// power · f_r · cos θr · f_j · e / max(d², d_min²); a directional VPL has d² = 1, d_min² = 0.
MVPL_INLINE vec3 vpl_pair(vec3 power, vec3 f_r, float cos_r, VplFactors e, float d2, float d_min2) {
    return power * f_r * cos_r * e.f * e.emitter / max(d2, d_min2);
}

#ifdef __cplusplus
}  // namespace mvpl::shared::math
#endif

#endif
