#include "engine/scene/camera.h"

namespace mvpl::scene {

CameraRay generate_camera_ray(const Camera& camera, int width, int height, const Vec2& film) {
    const float tan_half = std::tan(0.5f * camera.yfov);
    const float aspect = float(width) / float(height);
    // Normalised device coordinates in [-1, 1], +y up.
    const float ndc_x = 2.0f * film.x / float(width) - 1.0f;
    const float ndc_y = 1.0f - 2.0f * film.y / float(height);
    const Vec3 local(ndc_x * tan_half * aspect, ndc_y * tan_half, -1.0f);
    const Vec3 dir = glm::normalize(Vec3(camera.camera_to_world * Vec4(local, 0.0f)));
    // The ray starts on the near plane, where the G-buffer's rasteriser clips: along it the view
    // depth grows as t / |local| (local.z = -1), so the plane is at t = znear · |local|. Starting
    // at the eye instead made `reference` and the CPU oracle see what `render` clips away — at
    // ordinary fields of view only surfaces grazing the camera, but near yfov = π (tan(yfov/2) in
    // the thousands) almost the whole image, which `render` then showed black.
    const float near = std::max(camera.znear, 0.0f) * glm::length(local);
    return {camera.position() + near * dir, dir};
}

Camera frame_bounds(const Bounds& bounds) {
    Camera camera;
    if (bounds.empty()) return camera;
    const Vec3 center = bounds.center();
    const Vec3 half = 0.5f * (bounds.hi - bounds.lo);
    const float radius = std::max(glm::length(half), 1e-6f);
    // Distance at which the bounding sphere fits the vertical field of view, measured from the
    // front face of the box so that the camera is outside it.
    const float distance = radius / std::sin(0.5f * camera.yfov);
    const Vec3 eye = center + Vec3(0.0f, 0.0f, std::max(distance, half.z + radius * 1e-3f));
    camera.camera_to_world = Mat4(1.0f);
    camera.camera_to_world[3] = Vec4(eye, 1.0f);
    camera.znear = radius * 1e-3f;
    return camera;
}

}  // namespace mvpl::scene
