#pragma once
// Mitsuba's <transform>: translate, rotate (axis and angle in degrees), scale, matrix (4×4 or
// 3×3, row-major as written) and lookat, each applied after the ones before it (left-multiplied),
// in double precision.
#include <pugixml.hpp>

#include "engine/core/math.h"

namespace mvpl::scene::mitsuba {

class Context;

// The <transform> element's matrix; fails at the offending child on a missing or non-finite
// number, a zero rotation axis, a lookat whose origin is its target or whose up is parallel to
// the view, or an unknown element.
DMat4 read_transform(const Context& ctx, pugi::xml_node transform);

// The object's `name` transform (to_world, to_uv), or the identity.
DMat4 object_transform(const Context& ctx, pugi::xml_node object, const char* name = "to_world");

}  // namespace mvpl::scene::mitsuba
