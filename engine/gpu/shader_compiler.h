#pragma once
// GLSL → SPIR-V with glslang, in process (the shading code is generated per scene at start-up,
// so there is no offline compile step). Vulkan- and glslang-free to include.
//
// Target: Vulkan 1.3 / SPIR-V 1.6. `#include "file.glsl"` (GL_GOOGLE_include_directive) is
// resolved against the embedded shaders: first next to the including file, then from shaders/.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace mvpl::gpu {

enum class ShaderStage { vertex, fragment, compute, geometry };

// Throws ShaderCompileError with one line per error, `NAME:LINE: error: text`, where NAME is
// name (or the included file the error is in). glslang stops at the first error (its cascading
// mode warns of unreliable error recovery), so there is usually one line. Thread-safe.
std::vector<uint32_t> compile_glsl(ShaderStage stage, std::string_view source,
                                   std::string_view name);

// The stage that a file extension stands for: .vert .frag .comp .geom. Throws GpuError otherwise.
ShaderStage stage_from_name(std::string_view name);

// What compile_glsl's output depends on besides the source: the glslang version and the
// target environment (keys the SPIR-V cache, spirv_cache.h).
std::string glslang_identity();

// compile_glsl(stage_from_name(name), embedded_shader(name), name).
std::vector<uint32_t> compile_embedded_shader(std::string_view name);

}  // namespace mvpl::gpu
