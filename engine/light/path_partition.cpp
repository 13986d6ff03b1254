#include "engine/light/path_partition.h"

#include <algorithm>
#include <vector>

#include "engine/light/specular_chain.h"

namespace mvpl::light {

bool leaves_vpl(const material::Bsdf& bsdf, const Vec3& wi, const ChainOptions& specular) {
    return wi.z > 0.0f && !continues_chain(bsdf, wi, specular);
}

ChainOptions path_chain_class(const ChainOptions& specular, EmitterType emitter) {
    return emitter == EmitterType::Environment ? ChainOptions{} : specular;
}

bool scene_may_need_caustics(const scene::Scene& scene, const ChainOptions& specular,
                             const LightSampler& lights) {
    const std::vector<bool> drawn = scene.drawn_materials();
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        const scene::Material& m = scene.materials[i];
        if (drawn[i] && m.metallic < 1.0f &&
            (m.transmission > 0.0f || m.transmission_texture.valid()))
            return true;
    }
    const std::vector<Emitter>& emitters = lights.emitters();
    const bool beside_environment =
        std::any_of(emitters.begin(), emitters.end(),
                    [](const Emitter& e) { return e.type != EmitterType::Environment; });
    return beside_environment && scene_may_chain(scene, specular);
}

}  // namespace mvpl::light
