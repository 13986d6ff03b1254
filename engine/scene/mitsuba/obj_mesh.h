#pragma once
// Wavefront OBJ as Mitsuba's `obj` shape reads it: v, vt, vn and f (polygons fan-triangulated,
// negative indices relative), one mesh for the whole file (groups and materials ignored: the
// XML assigns the BSDF), vertices shared per (v, vt, vn) triple, and vt's v flipped
// (Mitsuba's flip_tex_coords, default true), so that v = 0 is the image's top row as in glTF.
#include <string>

#include "engine/scene/scene.h"

namespace mvpl::scene::mitsuba {

// Normals only where every face vertex names one. Throws InputError naming the file and line.
Mesh read_obj_mesh(const std::string& path, bool flip_tex_coords = true);

}  // namespace mvpl::scene::mitsuba
