#include "engine/trace/shading_point.h"

namespace mvpl::trace {

ShadingPoint make_shading_point(const material::SceneMaterials& materials,
                                const SurfaceInteraction& si) {
    // A solid's side is its inside (Bsdf refracts with 1/ior there), never flipped away.
    const bool flip =
        !si.front_face && materials.double_sided(si.material) && !materials.solid(si.material);
    const float side = flip ? -1.0f : 1.0f;
    const Vec3 ng = side * si.ng;
    const Vec3 ns = side * si.ns;
    material::SurfacePoint point;
    point.uv0 = si.uv0;
    point.uv1 = si.uv1;
    point.color = si.color;
    Vec3 n = ns;
    if (materials.has_normal_node(si.material)) {
        const Vec3 bitangent = si.tangent_sign * glm::cross(ns, si.dpdu);
        point.frame = Frame(si.dpdu, bitangent, ns);
        n = materials.normal(si.material, point);
    }
    return ShadingPoint{si.p, ng, Frame(n), material::Bsdf(materials.closure(si.material, point))};
}

}  // namespace mvpl::trace
