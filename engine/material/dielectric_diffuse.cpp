#include "engine/material/dielectric_diffuse.h"

#include "shaders/shared/closure_eval.h"

namespace mvpl::material {

DielectricLayer dielectric_layer(const Rgb& specular_color, float specular, float ior) {
    DielectricLayer layer;
    layer.f0 = shared::math::dielectric_f0(specular_color, specular, ior);
    layer.f90 = specular;
    layer.f0_max = max_component(layer.f0);
    return layer;
}

Rgb dielectric_diffuse_eval(const Rgb& base_color, const DielectricLayer& layer, float alpha,
                            const Vec3& wo, const Vec3& wi) {
    // The metal-rough mix without its metal (shaders/shared/closure_eval.h).
    const shared::math::ReflectionLobes lobes =
        shared::math::reflection_lobes(base_color, 0.0f, alpha, layer.f0, layer.f90, false);
    return shared::math::metal_rough_reflection(lobes, kLocalNormal, wo, wi);
}

}  // namespace mvpl::material
