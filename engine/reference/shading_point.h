#pragma once
// A surface point made ready for shading: the side the ray arrived on decided (glTF doubleSided),
// the normal map applied, the closure resolved.
#include "engine/core/math.h"
#include "engine/material/bsdf.h"
#include "engine/scene/scene.h"
#include "engine/trace/interaction.h"

namespace mvpl::reference {

struct ShadingPoint {
    Vec3 p;
    Vec3 ng;      // geometric normal on the side the shading happens
    Frame frame;  // shading frame, n = shading normal
    material::Bsdf bsdf;
};

// A back-face hit on a one-sided material shades with the unflipped normal, so its BSDF is zero
// for the arriving direction: the surface is black from behind, as Mitsuba's one-sided BSDFs.
ShadingPoint make_shading_point(const scene::Scene& scene, const trace::SurfaceInteraction& si);

}  // namespace mvpl::reference
