#include "engine/light/virtual_sphere.h"

#include "engine/material/microfacet.h"
#include "shaders/shared/virtual_sphere.h"

namespace mvpl::light {

material::ClosureParams widen_closure(const material::ClosureParams& params, float spread2) {
    if (!(spread2 > 0.0f) || params.is_lambertian()) return params;
    material::ClosureParams p = params;
    p.roughness = shared::vsl_roughness(material::roughness_to_alpha(p.roughness), spread2);
    return p;
}

}  // namespace mvpl::light
