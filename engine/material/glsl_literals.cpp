#include "engine/material/glsl_literals.h"

#include <cstdio>

namespace mvpl::material {

std::string glsl_number(float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", double(v));
    std::string s(buf);
    if (s.find_first_of(".e") == std::string::npos) s += ".0";
    return s;
}

std::string glsl_vec2(const Vec2& v) {
    return "vec2(" + glsl_number(v.x) + ", " + glsl_number(v.y) + ")";
}

std::string glsl_vec4(const Vec4& v) {
    return "vec4(" + glsl_number(v.x) + ", " + glsl_number(v.y) + ", " + glsl_number(v.z) + ", " +
           glsl_number(v.w) + ")";
}

}  // namespace mvpl::material
