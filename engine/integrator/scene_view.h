#pragma once
// What an estimate is of: the scene, its BVH and lights, and the camera.
#include "engine/light/light_sampler.h"
#include "engine/scene/scene.h"
#include "engine/trace/accel.h"

namespace mvpl::integrator {

struct SceneView {
    const scene::Scene* scene = nullptr;
    const trace::Accel* accel = nullptr;
    const light::LightSampler* lights = nullptr;
    const scene::Camera* camera = nullptr;
};

}  // namespace mvpl::integrator
