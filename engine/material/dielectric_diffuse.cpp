#include "engine/material/dielectric_diffuse.h"

#include "engine/material/lambertian.h"

namespace mvpl::material {

DielectricLayer dielectric_layer(const Rgb& specular_color, float specular, float ior) {
    DielectricLayer layer;
    // The clamp to 1 comes before the multiplication by `specular`, as the extension specifies,
    // so that F0 ≤ F90 = specular always holds.
    layer.f0 = glm::min(f0_from_ior(ior) * specular_color, Rgb(1.0f)) * specular;
    layer.f90 = specular;
    layer.f0_max = max_component(layer.f0);
    return layer;
}

Rgb dielectric_diffuse_eval(const Rgb& base_color, const DielectricLayer& layer, float alpha,
                            const Vec3& wo, const Vec3& wi) {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return Rgb(0.0f);
    Rgb f = dielectric_diffuse_weight(layer, wo.z, wi.z) * lambertian_eval(base_color, wo, wi);
    if (const std::optional<MicrofacetReflection> r = ggx_reflection(wo, wi, alpha)) {
        f += dielectric_fresnel(layer, r->cos_oh) * r->dv;
    }
    return f;
}

}  // namespace mvpl::material
