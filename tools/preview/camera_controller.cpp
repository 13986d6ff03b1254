#include "tools/preview/camera_controller.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace mvpl::preview {
namespace {
// Short of the poles, where the look-at frame with world up degenerates.
constexpr float kMaxPitch = 1.55f;
}  // namespace

CameraController::CameraController(const scene::Camera& camera, const scene::Bounds& bounds)
    : m_initial(camera),
      m_diagonal(std::max(bounds.diagonal(), 1e-3f)),
      m_center(bounds.empty() ? Vec3(0.0f) : bounds.center()) {
    reset();
}

void CameraController::reset() {
    m_camera = m_initial;
    const Vec3 eye = m_initial.position();
    const Vec3 forward = -glm::normalize(Vec3(m_initial.camera_to_world[2]));
    // The target: on the view axis, as far as the scene's centre is.
    m_distance = std::max(glm::dot(m_center - eye, forward), 0.1f * m_diagonal);
    m_target = eye + forward * m_distance;
    const Vec3 back = -forward;  // target → eye
    m_pitch = std::asin(std::clamp(back.y, -1.0f, 1.0f));
    m_yaw = std::atan2(back.x, back.z);
}

void CameraController::set_fov(float yfov) {
    m_initial.yfov = yfov;
    m_camera.yfov = yfov;
}

void CameraController::update() {
    const Vec3 back(std::cos(m_pitch) * std::sin(m_yaw), std::sin(m_pitch),
                    std::cos(m_pitch) * std::cos(m_yaw));
    const Vec3 eye = m_target + back * m_distance;
    // lookAt gives world → camera with the camera looking down −Z: invert for camera → world.
    m_camera.camera_to_world = glm::inverse(glm::lookAt(eye, m_target, Vec3(0.0f, 1.0f, 0.0f)));
}

void CameraController::orbit(float yaw_degrees, float pitch_degrees) {
    m_yaw += glm::radians(yaw_degrees);
    m_pitch = std::clamp(m_pitch + glm::radians(pitch_degrees), -kMaxPitch, kMaxPitch);
    update();
}

void CameraController::pan(float right, float up) {
    const float height = 2.0f * m_distance * std::tan(0.5f * m_camera.yfov);
    const Vec3 r = Vec3(m_camera.camera_to_world[0]);
    const Vec3 u = Vec3(m_camera.camera_to_world[1]);
    m_target += (r * right + u * up) * height;
    update();
}

void CameraController::zoom(float factor) {
    m_distance = std::clamp(m_distance * factor, 1e-4f * m_diagonal, 100.0f * m_diagonal);
    update();
}

void CameraController::fly(float forward, float right, float up) {
    const Vec3 f = -Vec3(m_camera.camera_to_world[2]);
    const Vec3 r = Vec3(m_camera.camera_to_world[0]);
    m_target += (f * forward + r * right + Vec3(0.0f, up, 0.0f)) * m_diagonal;
    update();
}

void CameraController::look(float yaw_degrees, float pitch_degrees) {
    const Vec3 eye = m_camera.position();
    m_yaw += glm::radians(yaw_degrees);
    m_pitch = std::clamp(m_pitch - glm::radians(pitch_degrees), -kMaxPitch, kMaxPitch);
    const Vec3 back(std::cos(m_pitch) * std::sin(m_yaw), std::sin(m_pitch),
                    std::cos(m_pitch) * std::cos(m_yaw));
    m_target = eye - back * m_distance;
    update();
}

}  // namespace mvpl::preview
