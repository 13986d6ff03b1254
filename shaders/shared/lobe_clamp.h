// A virtual spherical light's pair clamped lobe by lobe (virtual_sphere.h, vsl_glossy_d2, which
// says why): the diffuse × diffuse product keeps max(d², d_min²), every product with a widened
// glossy lobe in it is divided by vsl_glossy_d2. Written once for C++
// (engine/light/vpl_contribution.cpp) and GLSL (shaders/render/shading_template.glsl, with glossy
// closures, after virtual_sphere.h and vpl_pair.h); common subset as in shading_math.h.
#ifndef MVPL_SHADERS_SHARED_LOBE_CLAMP_H
#define MVPL_SHADERS_SHARED_LOBE_CLAMP_H

#ifdef __cplusplus
#include "shaders/shared/virtual_sphere.h"
#include "shaders/shared/vpl_pair.h"

namespace mvpl::shared::math {
using ::mvpl::shared::vsl_glossy_d2;
#endif

// Whether a pair is clamped lobe by lobe: a sphere (spread2 > 0) with a glossy lobe at either
// end, and a clamp to release (d_min² > 0).
MVPL_INLINE bool clamps_by_lobe(float spread2, float d_min2, bool glossy_pair) {
    return spread2 > 0.0f && d_min2 > 0.0f && glossy_pair;
}

// vpl_pair's radiance with the clamp lobe by lobe; f_r_diffuse: the receiver's diffuse lobe
// alone. The glossy part is what the full product has beyond the diffuse one.
MVPL_INLINE vec3 vpl_pair_by_lobe(vec3 power, vec3 f_r, vec3 f_r_diffuse, float cos_r, VplFactors e,
                                  float d2, float vsl_r2, float d_min2) {
    const vec3 diffuse = f_r_diffuse * e.f_diffuse;
    const vec3 glossy = max(f_r * e.f - diffuse, vec3(0.0f));
    return power * cos_r * e.emitter *
           (diffuse / max(d2, d_min2) + glossy / vsl_glossy_d2(d2, vsl_r2, d_min2));
}

#ifdef __cplusplus
}  // namespace mvpl::shared::math
#endif

#endif
