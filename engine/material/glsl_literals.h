#pragma once
// GLSL literals for generated code: "%.9g" reads back as the same float, and a literal always
// has a '.' or an exponent so that GLSL types it float.
#include <string>

#include "engine/core/math.h"

namespace mvpl::material {

std::string glsl_number(float v);
std::string glsl_vec2(const Vec2& v);
std::string glsl_vec4(const Vec4& v);

}  // namespace mvpl::material
