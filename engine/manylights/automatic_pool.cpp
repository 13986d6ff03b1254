#include "engine/manylights/automatic_pool.h"

#include <vector>

namespace mvpl::manylights {

bool diffuse_interior(const scene::Scene& scene) {
    if (scene.environment.active()) return false;
    const std::vector<bool> drawn = scene.drawn_materials();
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        const scene::Material& m = scene.materials[i];
        if (!drawn[i] || m.unlit()) continue;
        if (m.shading == scene::ShadingModel::SpecGloss || m.metallic > 0.0f || m.specular > 0.0f ||
            m.transmission > 0.0f)
            return false;
    }
    return true;
}

uint32_t automatic_pool(const scene::Scene& scene, std::string_view sampler, double time_budget,
                        bool cpu_device) {
    const double shortest = sampler == "mc"           ? kAutomaticMinSeconds
                            : sampler == "metropolis" ? kAutomaticMinSecondsMetropolis
                                                      : 0.0;
    const bool pays =
        cpu_device && shortest > 0.0 && time_budget >= shortest && diffuse_interior(scene);
    return pays ? kAutomaticPool : 0;
}

}  // namespace mvpl::manylights
