#pragma once
#include <optional>

#include "engine/core/math.h"
#include "engine/scene/bounds.h"
#include "engine/scene/scene.h"

namespace mvpl::scene {

// Primary ray through a point of the image plane; `film` is in pixels, (0,0) the top-left corner
// of the image and (width, height) the bottom-right. The horizontal field of view follows from
// the image aspect (glTF's aspectRatio is ignored: `--res` decides). The ray starts where it
// crosses the near plane (view depth camera.znear), glTF's near clipping plane, so that every
// renderer sees the same surfaces: what lies closer to the camera plane is not visible.
struct CameraRay {
    Vec3 origin;     // on the near plane, not at the eye
    Vec3 direction;  // unit
};
CameraRay generate_camera_ray(const Camera& camera, int width, int height, const Vec2& film);

// The inverse of generate_camera_ray: where the line from the eye to `p` crosses the image plane,
// in film pixels (possibly outside the image), and the cosine between that line and the view
// axis; none where p is not in front of the eye.
struct FilmPoint {
    Vec2 film;
    float cos_theta;
};
std::optional<FilmPoint> project_to_film(const Camera& camera, int width, int height,
                                         const Vec3& p);

// Whether `up` and `forward` span a camera frame: both finite and the sine of the angle between
// them at least kMinFrameSine, so that the orthogonalised up (and the right vector, their cross)
// is the file's direction and not rounding noise or NaN. Every loader checks its sensors' columns
// with it, and choose_camera the camera chosen.
bool spans_camera_frame(const DVec3& up, const DVec3& forward);
// The same for a camera's frame: its 3×3 part finite and of full rank.
bool has_camera_frame(const Camera& camera);

// A camera outside the bounds looking at their centre from a three-quarter view (from +X, +Y,
// +Z: 45° round, 30° up, as glTF viewers frame a model), far enough that the bounding sphere
// fits the vertical field of view.
Camera frame_bounds(const Bounds& bounds);

// A camera at `eye` looking at `target`, `up` as near the image's up as it is orthogonal to the
// view (+Z instead when the view is along `up`); yfov in radians. Eye and target must differ.
Camera look_at_camera(const Vec3& eye, const Vec3& target, const Vec3& up, float yfov, float znear);

}  // namespace mvpl::scene
