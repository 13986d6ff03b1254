// The common subset of C++ and GLSL that the layouts under shaders/shared are written in, after
// Falcor's HostDeviceShared.slangh: each layout is defined once, in a header that C++ includes
// as it is and GLSL stages include textually (engine/render/shader_program.cpp, expand_template,
// or glslang's GL_GOOGLE_include_directive for the stages compiled without a template).
//
// Rules for a shared struct, because C++ cannot give a 12-byte vec3 the 16-byte alignment that
// std140/std430 give it (a C++ type's size is a multiple of its alignment): the host twins below
// have the GLSL sizes and 4-byte alignment, so the C++ compiler adds no padding, and the header
// places every member where std430 puts it itself — each vec3 on a 16-byte boundary followed by
// a scalar, vec4 and mat4 on 16, vec2 and uvec2 on 8. MVPL_STD430_MEMBER checks one member: with
// no implicit padding, C++ and std430 agree on every offset exactly when each member's C++ offset
// is a multiple of its std430 alignment (scalars, always). std140 lays such a struct out as std430
// does as long as it holds no arrays and no nested structs; a std140 array of it also needs a
// size that is a multiple of 16.
//
// Include guards rather than #pragma once: GLSL stages see these files too. Nothing between the
// #ifdef __cplusplus lines may use what glslang cannot tokenise (no character literals).
#ifndef MVPL_SHADERS_SHARED_PRELUDE_H
#define MVPL_SHADERS_SHARED_PRELUDE_H

#ifdef __cplusplus

#include <cstddef>
#include <cstdint>

namespace mvpl::shared {

using uint = uint32_t;
using vec2 = float[2];
using vec3 = float[3];
using vec4 = float[4];
using uvec2 = uint32_t[2];
using uvec4 = uint32_t[4];
using mat4 = float[16];  // column-major, as glm and GLSL store it

// The std430 base alignment of each host twin: scalars 4, two-component vectors 8, three- and
// four-component vectors and mat4 (four vec4 columns) 16.
template <class T>
inline constexpr size_t kStd430Align = 4;
template <class T, size_t N>
inline constexpr size_t kStd430Align<T[N]> = N == 2 ? 8 : 16;

}  // namespace mvpl::shared

#define MVPL_SHARED_BEGIN namespace mvpl::shared {
#define MVPL_SHARED_END }
// S::m lies where std430 (and std140, for S without arrays) puts it.
#define MVPL_STD430_MEMBER(S, m)                                                      \
    static_assert(offsetof(S, m) % ::mvpl::shared::kStd430Align<decltype(S::m)> == 0, \
                  #S "::" #m " is not where std430 puts it")

#else

#define MVPL_SHARED_BEGIN
#define MVPL_SHARED_END

#endif

#endif
