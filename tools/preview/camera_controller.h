#pragma once
// Camera control for the preview: orbit around a target (left drag), pan (middle or shift+left
// drag), zoom (wheel), fly (WASD moves, right drag looks around), reset (R). The scene's own
// camera is returned untouched until the first move, so that an unmoved preview renders exactly
// the view `mvpl render` does. World up is +Y (glTF).
#include "engine/scene/bounds.h"
#include "engine/scene/scene.h"

namespace mvpl::preview {

class CameraController {
public:
    CameraController(const scene::Camera& camera, const scene::Bounds& bounds);

    const scene::Camera& camera() const { return m_camera; }
    void reset();
    // The vertical field of view in radians (kept by reset()).
    void set_fov(float yfov);

    // Angles in degrees: yaw about world up, pitch about the camera's right axis.
    void orbit(float yaw_degrees, float pitch_degrees);
    // Moves camera and target in the view plane by fractions of the view's height at the target.
    void pan(float right, float up);
    // Distance to the target times factor (< 1 moves closer).
    void zoom(float factor);
    // Moves camera and target along the view (forward), right and world up, in scene diagonals.
    void fly(float forward, float right, float up);
    // Turns the view about the eye (the target moves).
    void look(float yaw_degrees, float pitch_degrees);

private:
    void update();  // m_camera from target, distance, yaw, pitch

    scene::Camera m_initial;
    scene::Camera m_camera;
    float m_diagonal;
    Vec3 m_center;
    Vec3 m_target{0.0f};
    float m_distance = 1.0f;
    float m_yaw = 0.0f;    // radians; direction from the target to the eye
    float m_pitch = 0.0f;  // radians
};

}  // namespace mvpl::preview
