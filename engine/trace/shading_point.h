#pragma once
// A surface point made ready for shading: the side the ray arrived on decided (glTF doubleSided),
// the material graph's normal node applied, the closure resolved — what the path tracer, the
// light tracer and the VPL receivers all evaluate.
#include "engine/core/math.h"
#include "engine/material/bsdf.h"
#include "engine/material/scene_materials.h"
#include "engine/trace/interaction.h"

namespace mvpl::trace {

struct ShadingPoint {
    Vec3 p;
    Vec3 ng;      // geometric normal on the side the shading happens
    Frame frame;  // shading frame, n = shading normal
    material::Bsdf bsdf;
};

// A back-face hit on a one-sided material shades with the unflipped normal, so its BSDF is zero
// for the arriving direction: the surface is black from behind, as Mitsuba's one-sided BSDFs.
// Transmissive closures are the exception (material/bsdf.h): a thin one scatters from both
// sides, a solid's unflipped frame tells its inside from its outside.
// Whether the world direction w lies on the same side of the geometric normal ng as its local z
// (the shading side) says: directions for which they disagree would leak through the surface.
inline bool same_side(const Vec3& w, const Vec3& ng, float local_z) {
    const float d = glm::dot(w, ng);
    return local_z > 0.0f ? d > 0.0f : (local_z < 0.0f && d < 0.0f);
}

ShadingPoint make_shading_point(const material::SceneMaterials& materials,
                                const SurfaceInteraction& si);

}  // namespace mvpl::trace
