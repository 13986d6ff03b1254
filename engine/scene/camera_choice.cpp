#include "engine/scene/camera_choice.h"

#include <string>

#include "engine/core/error.h"
#include "engine/scene/camera.h"

namespace mvpl::scene {

Camera choose_camera(const Scene& scene, const CameraChoice& choice) {
    Camera camera = scene.camera;
    if (choice.index >= 0) {
        if (size_t(choice.index) >= scene.cameras.size()) {
            const size_t n = scene.cameras.size();
            throw UsageError(
                "--camera " + std::to_string(choice.index) + ": " + scene.path +
                (n == 0 ? " has no perspective camera"
                        : " has " + std::to_string(n) + " perspective camera" +
                              (n == 1 ? " (0)" : "s (0.." + std::to_string(n - 1) + ")")));
        }
        camera = scene.cameras[size_t(choice.index)];
    }
    if (choice.look_at) {
        if (!(glm::length(choice.eye - choice.target) > 0.0f))
            throw UsageError("--look-at: the eye is the target");
        camera = look_at_camera(choice.eye, choice.target, choice.up, camera.yfov, camera.znear);
    }
    if (choice.fov_degrees > 0.0f) camera.yfov = glm::radians(choice.fov_degrees);
    // The loaders refuse their own degenerate sensors; this is the last guard before any ray is
    // made (render, reference, vpls alike), whichever camera was chosen.
    if (!has_camera_frame(camera)) {
        throw InputError(scene.path, (choice.index >= 0 ? "camera " + std::to_string(choice.index)
                                                        : std::string("the camera")) +
                                         " has a degenerate frame (its up along its view, or not "
                                         "finite)");
    }
    return camera;
}

}  // namespace mvpl::scene
