#include "engine/scene/camera.h"

#include <cmath>

namespace mvpl::scene {

namespace {

// Below this sine between up and forward the orthogonalised up is dominated by rounding: the
// frame is stored in float (relative precision 6e-8), and 1e-6 leaves it a few bits of its own.
constexpr double kMinFrameSine = 1e-6;

bool finite(const DVec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

bool spans_camera_frame(const DVec3& up, const DVec3& forward) {
    if (!finite(up) || !finite(forward)) return false;
    const double scale = glm::length(up) * glm::length(forward);
    return std::isfinite(scale) && scale > 0.0 &&
           glm::length(glm::cross(up, forward)) >= kMinFrameSine * scale;
}

bool has_camera_frame(const Camera& camera) {
    const DMat4 m(camera.camera_to_world);
    const DVec3 right(m[0]), up(m[1]), back(m[2]);
    if (!finite(right) || !finite(DVec3(m[3])) || !spans_camera_frame(up, back)) return false;
    // Full rank: the right vector leaves the plane of up and back by the same margin.
    const double volume = std::abs(glm::dot(glm::cross(up, back), right));
    return volume >= kMinFrameSine * glm::length(up) * glm::length(back) * glm::length(right);
}

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

std::optional<FilmPoint> project_to_film(const Camera& camera, int width, int height,
                                         const Vec3& p) {
    const Vec3 from_eye = p - camera.position();
    const float d = glm::length(from_eye);
    if (!(d > 0.0f)) return std::nullopt;
    const Mat3 to_camera = glm::transpose(Mat3(camera.camera_to_world));  // rigid: R⁻¹ = Rᵀ
    const Vec3 local = to_camera * (from_eye / d);
    const float cos_theta = -local.z;  // the camera looks down its −Z
    if (!(cos_theta > 0.0f)) return std::nullopt;
    const float tan_half = std::tan(0.5f * camera.yfov);
    const float aspect = float(width) / float(height);
    const float ndc_x = local.x / (cos_theta * tan_half * aspect);
    const float ndc_y = local.y / (cos_theta * tan_half);
    return FilmPoint{
        Vec2(0.5f * (ndc_x + 1.0f) * float(width), 0.5f * (1.0f - ndc_y) * float(height)),
        cos_theta};
}

Camera frame_bounds(const Bounds& bounds) {
    Camera camera;
    if (bounds.empty()) return camera;
    const Vec3 center = bounds.center();
    const Vec3 half = 0.5f * (bounds.hi - bounds.lo);
    const float radius = std::max(glm::length(half), 1e-6f);
    // The distance at which the bounding sphere fits the vertical field of view; it is more than
    // the radius, so the camera is outside the box.
    const float distance = radius / std::sin(0.5f * camera.yfov);
    const float elevation = glm::radians(30.0f);
    const float azimuth = glm::radians(45.0f);
    const Vec3 from(std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                    std::cos(elevation) * std::cos(azimuth));
    return look_at_camera(center + distance * from, center, Vec3(0.0f, 1.0f, 0.0f), camera.yfov,
                          radius * 1e-3f);
}

Camera look_at_camera(const Vec3& eye, const Vec3& target, const Vec3& up, float yfov,
                      float znear) {
    const Vec3 back = glm::normalize(eye - target);  // the camera looks down its -Z
    Vec3 u = glm::length(up) > 0.0f ? glm::normalize(up) : Vec3(0.0f, 1.0f, 0.0f);
    if (std::abs(glm::dot(u, back)) > 0.999f) u = Vec3(0.0f, 0.0f, 1.0f);
    if (std::abs(glm::dot(u, back)) > 0.999f) u = Vec3(1.0f, 0.0f, 0.0f);
    const Vec3 right = glm::normalize(glm::cross(u, back));
    const Vec3 true_up = glm::cross(back, right);
    Camera camera;
    camera.camera_to_world =
        Mat4(Vec4(right, 0.0f), Vec4(true_up, 0.0f), Vec4(back, 0.0f), Vec4(eye, 1.0f));
    camera.yfov = yfov;
    camera.znear = znear;
    return camera;
}

}  // namespace mvpl::scene
