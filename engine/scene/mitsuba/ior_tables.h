#pragma once
// Mitsuba's named materials: the conductors' complex index of refraction (η, k) and the
// dielectrics' index of refraction, as RGB / scalars for an RGB renderer.
#include <optional>
#include <string>

#include "engine/core/color.h"

namespace mvpl::scene::mitsuba {

struct ComplexIor {
    Rgb eta;
    Rgb k;
};

// A conductor by Mitsuba's name ("Au", "Cu", "Al", …); nullopt for an unknown name. "none" is
// the perfect mirror (Mitsuba: η = 0, k = 1).
std::optional<ComplexIor> conductor_ior(const std::string& name);
// The names conductor_ior knows, for messages.
std::string conductor_names();

// A dielectric by Mitsuba's name ("bk7", "water", "diamond", …); nullopt when unknown.
std::optional<float> dielectric_ior(const std::string& name);

// Reflectance at normal incidence of a conductor against a medium of index `outside`:
// ((η − 1)² + k²) / ((η + 1)² + k²) with η, k relative to it. What the Schlick conductor
// (engine/material/conductor.h) takes as F0.
Rgb conductor_f0(const ComplexIor& ior, float outside);

}  // namespace mvpl::scene::mitsuba
