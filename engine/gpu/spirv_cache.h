#pragma once
// SPIR-V cache on disk: compile_glsl's output stored under a key that hashes the source, the
// stage and the compiler (glslang version and target), so that a warm start skips glslang. The
// cache can never fail a compile: an unreadable, corrupt or unwritable cache falls back to
// compiling, and entries are written to a temporary file and renamed into place (atomic on
// POSIX), so that concurrent renders never read half a file. Vulkan- and glslang-free.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "engine/gpu/shader_compiler.h"

namespace mvpl::gpu {

struct SpirvCacheOptions {
    bool enabled = true;
    // Empty: default_spirv_cache_directory().
    std::filesystem::path directory;
};

// $XDG_CACHE_HOME/mvpl, else $HOME/.cache/mvpl; empty when neither variable is set.
std::filesystem::path default_spirv_cache_directory();

// The cache key: 64-bit FNV-1a of the compiler identity, the stage and the source, as 16 hex
// digits.
std::string spirv_cache_key(ShaderStage stage, std::string_view source);

// compile_glsl through the cache. hit (optional) says whether the cache answered.
std::vector<uint32_t> compile_glsl_cached(ShaderStage stage, std::string_view source,
                                          std::string_view name, const SpirvCacheOptions& options,
                                          bool* hit = nullptr);

}  // namespace mvpl::gpu
