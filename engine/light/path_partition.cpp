#include "engine/light/path_partition.h"

#include <vector>

#include "engine/light/specular_chain.h"

namespace mvpl::light {

bool leaves_vpl(const material::Bsdf& bsdf, const Vec3& wi, const ChainOptions& specular) {
    return wi.z > 0.0f && !continues_chain(bsdf, wi, specular);
}

bool scene_may_need_caustics(const scene::Scene& scene, const ChainOptions& specular) {
    const std::vector<bool> drawn = scene.drawn_materials();
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        const scene::Material& m = scene.materials[i];
        if (drawn[i] && m.metallic < 1.0f &&
            (m.transmission > 0.0f || m.transmission_texture.valid()))
            return true;
    }
    return scene_may_chain(scene, specular);
}

}  // namespace mvpl::light
