// KHR_lights_punctual's spot falloff, written once for the light sampler
// (engine/light/light_sampler.cpp, spot_attenuation), the CPU oracle's spot VPLs
// (engine/light/vpl_contribution.cpp) and the shading pass (shaders/render/shading_template.glsl):
// the smooth step of the cosine between the cone's outer and inner angles, squared as the
// extension's sample code has it. A cone whose inner and outer angles meet is widened to a
// difference of 1e-3 in cosine, so that the step stays finite.
#ifndef MVPL_SHADERS_SHARED_SPOT_FALLOFF_H
#define MVPL_SHADERS_SHARED_SPOT_FALLOFF_H

#include "prelude.h"

#ifdef __cplusplus
#include <algorithm>
#define MVPL_SPOT_FN inline
#else
#define MVPL_SPOT_FN
#endif

MVPL_SHARED_BEGIN

#ifdef __cplusplus
using std::clamp;
using std::max;
#endif

// cos_angle: between the spot's axis and the direction it sends light in.
MVPL_SPOT_FN float spot_falloff(float cos_inner, float cos_outer, float cos_angle) {
    const float scale = 1.0f / max(1e-3f, cos_inner - cos_outer);
    const float t = clamp((cos_angle - cos_outer) * scale, 0.0f, 1.0f);
    return t * t;
}

MVPL_SHARED_END

#undef MVPL_SPOT_FN

#endif
