#include "engine/reference/shading_point.h"

#include "engine/material/material_eval.h"

namespace mvpl::reference {

ShadingPoint make_shading_point(const scene::Scene& scene, const trace::SurfaceInteraction& si) {
    const scene::Material& material = scene.materials[si.material];
    const bool flip = !si.front_face && material.double_sided;
    const float side = flip ? -1.0f : 1.0f;
    const Vec3 ng = side * si.ng;
    const Vec3 ns = side * si.ns;
    const material::SurfaceUv uv{si.uv0, si.uv1};
    Vec3 n = ns;
    if (material.normal_texture.valid()) {
        const Vec3 bitangent = si.tangent_sign * glm::cross(ns, si.dpdu);
        n = material::apply_normal_map(material, scene.textures, uv, Frame(si.dpdu, bitangent, ns));
    }
    return ShadingPoint{si.p, ng, Frame(n),
                        material::Bsdf(material::resolve_closure(material, scene.textures, uv))};
}

}  // namespace mvpl::reference
