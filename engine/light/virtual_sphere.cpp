#include "engine/light/virtual_sphere.h"

#include <cmath>

#include "engine/material/microfacet.h"
#include "shaders/shared/virtual_sphere.h"

namespace mvpl::light {

material::ClosureParams widen_closure(const material::ClosureParams& params, float spread2) {
    if (!(spread2 > 0.0f) || params.is_lambertian()) return params;
    material::ClosureParams p = params;
    // The perceptual roughness whose α (roughness², microfacet.h) is the widened α; the GLSL of
    // shading_template.glsl computes it with the same operations.
    p.roughness = std::sqrt(shared::vsl_alpha(material::roughness_to_alpha(p.roughness), spread2));
    return p;
}

}  // namespace mvpl::light
