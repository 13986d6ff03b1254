#include "engine/light/default_sky.h"

#include <numbers>

#include "engine/light/light_sampler.h"

namespace mvpl::light {

bool SceneLighting::lights_itself() const {
    return has_punctual || has_environment || emitted_share() >= kMinEmittedShare;
}

SceneLighting scene_lighting(const scene::Scene& scene) {
    SceneLighting l;
    const LightSampler sampler(scene);
    // Emitters that send nothing do not count (as LightSampler::empty, the rule before this one).
    for (const Emitter& e : sampler.emitters()) {
        if (!(e.power > 0.0f)) continue;
        if (e.type == EmitterType::Triangle) {
            l.emitted += double(e.power);
        } else if (e.type == EmitterType::Environment) {
            l.has_environment = true;
        } else {
            l.has_punctual = true;
        }
    }
    const double r = double(sampler.scene_radius());
    l.unit_sky = 4.0 * std::numbers::pi * std::numbers::pi * r * r;
    return l;
}

}  // namespace mvpl::light
