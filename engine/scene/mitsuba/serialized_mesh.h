#pragma once
// Mitsuba's `serialized` mesh format (Mitsuba 0.6 documentation, "Serialized mesh format"): per
// shape a 0x041C/version header and a zlib stream of flags, [name], vertex and triangle counts,
// positions, optional normals, texture coordinates and colours, and indices; the file ends with
// a table of each shape's offset and the shape count.
#include <string>

#include "engine/scene/scene.h"

namespace mvpl::scene::mitsuba {

// Shape `shape_index` of the file. `face_normals` is set when the shape asks for flat shading.
// Throws InputError naming the file and the defect (bad header, index beyond the table, corrupt
// or truncated zlib data, an index out of range, a non-finite value).
Mesh read_serialized_mesh(const std::string& path, int shape_index, bool* face_normals = nullptr);

}  // namespace mvpl::scene::mitsuba
