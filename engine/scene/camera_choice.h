#pragma once
// Which camera a command renders from: the file's first (the default), its camera N
// (`--camera N`), or one placed on the command line (`--look-at`), each with an optional vertical
// field of view (`--fov`). Applied once, after loading, before anything reads the camera.
#include "engine/core/math.h"
#include "engine/scene/scene.h"

namespace mvpl::scene {

struct CameraChoice {
    int index = -1;  // Scene::cameras[index]; -1: the scene's camera
    bool look_at = false;
    Vec3 eye{0.0f};
    Vec3 target{0.0f, 0.0f, -1.0f};
    Vec3 up{0.0f, 1.0f, 0.0f};
    float fov_degrees = 0.0f;  // vertical; 0: the camera's own
};

// The camera `choice` names in `scene`. Throws UsageError when the file has no camera N (naming
// how many it has) or the look-at eye is the target.
Camera choose_camera(const Scene& scene, const CameraChoice& choice);

}  // namespace mvpl::scene
