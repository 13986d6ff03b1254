#pragma once
// Errors from the Vulkan layer. Not an InputError: a missing driver or layer is an environment
// problem, reported as `mvpl: internal error: …` unless a command catches it.
#include <stdexcept>
#include <string>

namespace mvpl::gpu {

// A Vulkan call failed, no usable device exists, or a request cannot be met (format, layer, …).
// The message names the call or the object and, for a VkResult, its symbolic name.
class GpuError : public std::runtime_error {
public:
    explicit GpuError(const std::string& what) : std::runtime_error(what) {}
};

// glslang rejected a shader. what(): one line per diagnostic, each `NAME:LINE: error: text`.
class ShaderCompileError : public GpuError {
public:
    explicit ShaderCompileError(const std::string& what) : GpuError(what) {}
};

}  // namespace mvpl::gpu
