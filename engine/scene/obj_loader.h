#pragma once
// Wavefront OBJ meshes via tinyobjloader (Debian's libtinyobjloader-dev). Polygons are
// fan-triangulated here (as PLY faces are), so that the same polygon mesh in both formats gives
// the same triangles. Materials from the .mtl file next to it: Kd → base colour, Ke → emission,
// both diffuse; faces without a material get the default grey diffuse one.
#include <string>

#include "engine/scene/scene.h"

namespace mvpl::scene {

// One mesh per material used, a camera framing the bounds, no punctual light. Throws InputError
// naming the file and the defect (a parse error, an index out of range, a non-finite vertex).
Scene load_obj(const std::string& path);

}  // namespace mvpl::scene
