#pragma once
// A surface closure: the material parameters resolved at one surface point (textures applied),
// all that a BSDF needs. VPLs carry one; the G-buffer stores one per pixel.
#include <algorithm>
#include <cstdint>

#include "engine/core/color.h"
#include "shaders/shared/closure.h"
#include "shaders/shared/closure_ranges.h"

namespace mvpl::material {

// The members, their defaults and the GLSL struct Closure come from one list
// (shaders/shared/closure.h): roughness is perceptual (glTF; the GGX alpha is roughness²),
// specular the KHR_materials_specular factor (0 removes the dielectric layer).
struct ClosureParams {
    MVPL_CLOSURE_PARAMS(MVPL_CLOSURE_MEMBER)

    // KHR_materials_transmission, on the CPU only (not in the X-macro: the GPU shades the
    // reflection of a transmissive surface, whose transmission the specular chains follow on the
    // CPU): the specular BTDF's tint times its weight, t · base colour (base_color above already
    // holds the diffuse share (1 − t) · base colour), before the (1 − metallic) of the mix.
    Rgb transmission{0.0f};
    // Without KHR_materials_volume (thickness 0) the surface is thin: the transmitted ray keeps
    // its direction. Otherwise it bounds a solid and refracts with `ior` inside.
    bool thin_walled = true;

    // Metallic 0 and no specular layer: a pure Lambertian, shaded by the cheap path. (Its
    // reflection: a transmission lobe is Bsdf's business, not the GPU closure type's.)
    bool is_lambertian() const { return metallic <= 0.0f && specular <= 0.0f; }
    bool transmits() const { return max_component(transmission) > 0.0f && metallic < 1.0f; }
};

// The parameters limited to the ranges glTF allows (NaN becomes the lower bound): base_color,
// metallic, roughness and specular in [0, 1]; specular_color and ior in [0, 1e6] (specular_color
// may exceed 1 by KHR_materials_specular; the cap only keeps infinities out, since F0 saturates
// at 1 long before). Bsdf applies this itself; every closure node returns it. The bounds are
// shaders/shared/closure_ranges.h's, which the GPU's clamp_closure applies too.
inline ClosureParams clamp_to_valid_ranges(const ClosureParams& p) {
    const auto unit = shared::math::clamp_unit;
    const auto non_negative = shared::math::clamp_non_negative;
    ClosureParams c = p;
    c.base_color = Rgb(unit(p.base_color.r), unit(p.base_color.g), unit(p.base_color.b));
    c.metallic = unit(p.metallic);
    c.roughness = unit(p.roughness);
    c.specular = unit(p.specular);
    c.specular_color = Rgb(non_negative(p.specular_color.r), non_negative(p.specular_color.g),
                           non_negative(p.specular_color.b));
    c.ior = non_negative(p.ior);
    c.transmission = Rgb(unit(p.transmission.r), unit(p.transmission.g), unit(p.transmission.b));
    return c;
}

// The closure with these parameters, limited to the glTF ranges: what every closure node
// resolves to (GLSL: clamp_closure in glsl_library.cpp).
inline ClosureParams make_closure(const Rgb& base_color, float metallic, float roughness,
                                  float specular, const Rgb& specular_color, float ior) {
    ClosureParams c;
    c.base_color = base_color;
    c.metallic = metallic;
    c.roughness = roughness;
    c.specular = specular;
    c.specular_color = specular_color;
    c.ior = ior;
    return clamp_to_valid_ranges(c);
}

// Closure types the shading code distinguishes, narrowest first. closure_type() of a closure is
// the narrowest type whose evaluator gives exactly Bsdf::eval.
enum class ClosureType : uint32_t { Lambertian = 0, Conductor = 1, Dielectric = 2, MetalRough = 3 };
inline constexpr int kClosureTypeCount = 4;
inline constexpr uint32_t closure_type_bit(ClosureType t) {
    return 1u << uint32_t(t);
}

inline ClosureType closure_type(const ClosureParams& params) {
    const ClosureParams c = clamp_to_valid_ranges(params);
    return ClosureType(shared::math::closure_type_of(c.metallic, c.specular));
}

}  // namespace mvpl::material
