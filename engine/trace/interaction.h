#pragma once
#include "engine/core/math.h"
#include "engine/scene/scene.h"
#include "engine/trace/accel.h"

namespace mvpl::trace {

// What the light transport needs to know about a ray's hit point.
struct SurfaceInteraction {
    Vec3 p;
    Vec3 ng;    // geometric normal of the triangle's winding (front face side), unit
    Vec3 ns;    // interpolated vertex normal, unit; flipped to ng's side if it was not
    Vec3 dpdu;  // tangent: from TANGENT when present, else from the UV parametrisation
    float tangent_sign = 1.0f;
    Vec2 uv0{0.0f};
    Vec2 uv1{0.0f};
    Vec4 color{1.0f};  // COLOR_0, white where the mesh has none
    int mesh = -1;
    int triangle = -1;
    int material = 0;
    bool front_face = true;  // the ray arrived on the side ng points to
};

// The vertex attributes that material graphs read (uv0, uv1, COLOR_0; no frame), interpolated at
// barycentric b = (b1, b2) of a triangle: what alpha tests and emission graphs evaluate.
material::SurfacePoint surface_attributes(const scene::Mesh& mesh, int triangle, const Vec2& b);

SurfaceInteraction make_interaction(const scene::Scene& scene, const Hit& hit, const Ray& ray);

}  // namespace mvpl::trace
