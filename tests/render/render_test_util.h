#pragma once
// CPU references for the render tests: ray casts against quads and the vpl.h contribution
// formulas evaluated with the CPU BRDF (engine/material/bsdf.h).
#include <optional>
#include <vector>

#include "engine/core/color.h"
#include "engine/core/math.h"
#include "engine/light/vpl.h"
#include "engine/material/closure.h"
#include "engine/scene/scene.h"

namespace mvpl::render::testing {

struct CpuHit {
    Vec3 p;
    Vec3 ng;  // winding normal
    Vec3 ns;  // interpolated vertex normal on ng's side
    int mesh = -1;
    bool front_face = true;
};

// The first hit of the ray through the point `subpixel` of pixel (x, y), its centre by default
// (scene::generate_camera_ray), among the scene's meshes, brute force over all triangles
// (Möller–Trumbore, double precision).
std::optional<CpuHit> cast_camera_ray(const scene::Scene& scene, int width, int height, int x,
                                      int y, Vec2 subpixel = Vec2(0.5f));
// Whether the segment from a to b hits any triangle of mesh (strictly between the ends).
bool segment_hits_mesh(const scene::Mesh& mesh, const Vec3& a, const Vec3& b);

// vpl.h's contribution of one VPL to a receiver at p with shading normal n (already on the
// shading side) and closure `receiver`, seen from `camera`; V = 1. Area and surface VPLs are
// virtual spherical lights of radius vsl_radius (world units; 0: points), clamped lobe by lobe
// (vpl.h), or as a whole with `clamp_whole` (the formula before issue 15, for comparison).
Rgb cpu_contribution(const light::Vpl& vpl, const Vec3& p, const Vec3& n,
                     const material::ClosureParams& receiver, const Vec3& camera, float d_min,
                     float vsl_radius = 0.0f, bool clamp_whole = false);

// A closure from a scene material's factors (what the G-buffer stores).
material::ClosureParams closure_of(const scene::Material& material);

}  // namespace mvpl::render::testing
