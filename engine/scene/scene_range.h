#pragma once
// The range of values the scene model promises everything downstream: what float32 positions,
// Embree's ray arithmetic and the float shaders can carry, with margin. Each loader checks what
// it reads against these where it reads it, so that a value beyond them is refused with the file,
// the place and the value (InputError, exit code 2) instead of overflowing later: an abort inside
// Embree, an `inf` literal in generated GLSL, a light dropped because its power became infinite.
// "Finite as a double" is not enough: a double of 1e300 is finite and a float of it is not.
#include <functional>
#include <numbers>
#include <string>

#include "engine/scene/scene.h"

namespace mvpl::scene {

// Largest |coordinate| of a world-space position (vertices, lights, cameras, translations), in
// metres. Two bounds, the lower one taken:
// - Embree's watertight ray-triangle test (robust mode, kernels/geometry/
//   triangle_intersector_pluecker.h) computes the depth T = 2·dot(v0, Ng) in float, v0 a vertex
//   relative to the ray origin and Ng a cross product of two edges: a cubic term. In a scene
//   within ±C, |v0| ≤ 2√3·C and |Ng| ≤ 12·C², so |T| ≤ 83·C³, which overflows FLT_MAX beyond
//   C ≈ 1.6e12 (Embree itself skips geometry beyond 1.8e18, and then misses or aborts).
// - Measured: the Cornell box renders the same scaled up to coordinates of 4.3e9 (`reference`
//   with direct light only, bit for bit) and 25–35% darker from 4.4e9 on, in `render` too; the
//   cause is not known yet (issue 19's report).
// 1e9 keeps a factor of four below the second and T at 8e28, nine orders below FLT_MAX; squared
// distances (≤ 12·C² ≈ 1e19) and triangle areas in the shaders are far from overflow. 1e9 m is
// two and a half times the distance to the Moon.
inline constexpr double kMaxCoordinate = 1e9;

// Smallest size of a scene's geometry (its bounding box's diagonal), in metres. Ray offsets and
// shadow biases are relative to the scene (trace/ray.h, render/shadow_pass.h): the Cornell box
// renders the same from 2·10⁻⁸ m across (scale 10⁻⁸) up (tests: from 10⁻⁶), and 0.2–20 % off its
// unit-scale image at 2·10⁻¹⁰ (path tracer, oracle and GPU; squared distances approach float's
// smallest normal numbers). 10⁻⁷ m, a tenth of a micrometre, keeps a factor of five above the
// last scale measured right.
inline constexpr double kMinSceneSize = 1e-7;

// Largest colour, intensity or other multiplicative factor (emissive factor × strength, a light's
// colour × intensity, specular colour, normal scale, texture-transform offset and scale, texture
// coordinates). Shaders multiply such a value in float with a few others of its kind and with
// BSDF values up to ≈1e7 (the GGX peak at the smallest roughness, microfacet.h):
// 1e15 · 1e7 · 1e7 = 1e29 stays nine orders below FLT_MAX. 1e15 is six orders above the brightest
// radiance a scene plausibly holds (the Sun's disk, ≈1.6e9 cd/m², taken 1:1 as W/(sr·m²)).
inline constexpr double kMaxFactor = 1e15;

// Largest flux, in watts, that all emitters of a scene may emit together: a VPL carries up to the
// total flux (times the Russian-roulette and Metropolis weights, ≲ 100) and the shading pass
// multiplies it by two BSDF values (≲ 8e6 each, the GGX peak at normal incidence) before dividing
// by the squared distance: 1e22 · 100 · 6.4e13 = 6.4e37 is still below FLT_MAX. Flux grows with
// the square of the scene's size (an area light's π·A·L, a directional light's π·r²·E), so this
// is what refuses the Sun's 1e5 W/m² over a scene of 1e9 m rather than rendering it black.
inline constexpr double kMaxPower = 1e22;

// A perspective camera's vertical field of view, radians. Below kMinYfov the directions through
// neighbouring pixels can no longer be told apart in float: in the largest image (16384 rows,
// tools/cli/arg_parser.cpp) a pixel then spans 1e-3 / 16384 ≈ 6e-8 rad, one float ulp of a unit
// direction (2^-24); in 1024 rows sixteen. (`render` composes its projection in float and loses
// a 1e-8 field of view earlier, a 1e-30 one entirely.) kMaxYfov keeps tan(yfov / 2) finite and
// the projection well defined in float (tan ≈ 1.7e6); how much of such a view the near plane
// clips is the camera's business (scene/camera.h), the same for every renderer.
inline constexpr double kMinYfov = 1e-3;
inline constexpr double kMaxYfov = std::numbers::pi - 1e-6;

// Throws InputError naming `path` when the scene's geometry is smaller than kMinSceneSize (a
// scene without triangles passes: it has no size to be wrong about).
void check_scene_size(const Scene& scene, const std::string& path);

// A double as a person would write it ("0.5", "1e+30"): the shortest text that reads back as the
// same value (as the same float when it is exactly one), so that a value and the limit it
// exceeds never read the same. How values and the limits above appear in messages.
std::string number_text(double value);

// The flux (W) each light and each emissive material of `scene` emits, and their sum, computed in
// double from the factors (an emissive texture only darkens: its texels are at most 1). Calls
// `fail` with a message naming the emitter (through `name_light` and `name_material`, which give
// the file's name for light i or material m) when the sum exceeds kMaxPower; `fail` must not
// return.
using EmitterName = std::function<std::string(int)>;
void check_emitted_power(const Scene& scene, const EmitterName& name_light,
                         const EmitterName& name_material,
                         const std::function<void(const std::string&)>& fail);

}  // namespace mvpl::scene
