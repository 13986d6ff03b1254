#include "engine/gpu/embedded_shaders.h"

#include <string>

#include "engine/gpu/gpu_error.h"

namespace mvpl::gpu {

std::optional<std::string_view> find_embedded_shader(std::string_view name) {
    for (const detail::EmbeddedShader* s = detail::kEmbeddedShaders; !s->name.empty(); ++s) {
        if (s->name == name) return s->source;
    }
    return std::nullopt;
}

std::string_view embedded_shader(std::string_view name) {
    if (const std::optional<std::string_view> source = find_embedded_shader(name)) return *source;
    throw GpuError("no embedded shader '" + std::string(name) +
                   "' (shaders/ is embedded at build time: re-run cmake after adding a file)");
}

std::vector<std::string_view> embedded_shader_names() {
    std::vector<std::string_view> names;
    for (const detail::EmbeddedShader* s = detail::kEmbeddedShaders; !s->name.empty(); ++s) {
        names.push_back(s->name);
    }
    return names;
}

}  // namespace mvpl::gpu
