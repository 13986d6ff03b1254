#pragma once
// Programmatic scenes for tests whose answer is known analytically.
#include <vector>

#include "engine/scene/scene.h"

namespace mvpl::test {

// A Lambertian material (metallic 0, no specular layer).
scene::Material diffuse_material(const Rgb& albedo);
// A quad p, p+a, p+a+b, p+b; its front face (and normal) is along cross(a, b).
scene::Mesh make_quad(const Vec3& p, const Vec3& a, const Vec3& b, int material);
// Icosphere of `subdivisions` levels (20·4^n triangles) with vertices on the sphere; normals
// point inwards when `inward`, and so do the front faces.
scene::Mesh make_icosphere(const Vec3& center, float radius, int subdivisions, bool inward,
                           int material);
// A point light of intensity I at the centre of a closed Lambertian sphere (level-5 icosphere,
// inward faces) of albedo a and radius R, the camera inside: every visible point has
// L = a·I / (π R² (1 − a)).
scene::Scene make_integrating_sphere(float albedo, float radius, float intensity);
// A 6 × 6 Lambertian floor (material 0, albedo 0.7) at y = 0 with `objects` on it (materials
// from 0 on), under a directional light of 2 W/m² travelling along (0.5, −1, 0.3), seen from
// (0, 4, 4).
scene::Scene floor_under_sun(std::vector<scene::Mesh> objects);
// A camera at `eye` looking at `target` with +Y up.
scene::Camera look_at(const Vec3& eye, const Vec3& target, float yfov);
// Scales every length of the scene by s (geometry, lights, camera). Radiance is scale-invariant;
// point and spot intensities are multiplied by s² so that irradiance stays the same.
void scale_scene(scene::Scene& scene, float s);

}  // namespace mvpl::test
