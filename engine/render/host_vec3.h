#pragma once
#include "engine/core/math.h"

namespace mvpl::render {

// A Vec3 into the host twin of a GLSL vec3 (shaders/shared/prelude.h, float[3]): GPU records
// (GpuVpl, GeometryVertex) keep 4-byte-aligned floats where glm's type may be padded or aligned
// otherwise.
inline void store(float out[3], const Vec3& v) {
    out[0] = v.x;
    out[1] = v.y;
    out[2] = v.z;
}

}  // namespace mvpl::render
