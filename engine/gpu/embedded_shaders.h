#pragma once
// The GLSL sources under shaders/, embedded at build time (cmake/EmbedShaders.cmake), so that
// `mvpl` needs no shader files at run time. Names are paths relative to shaders/, e.g.
// "test/saxpy.comp".
#include <optional>
#include <string_view>
#include <vector>

namespace mvpl::gpu {

// The source text; throws GpuError naming the shader when there is none.
std::string_view embedded_shader(std::string_view name);
std::optional<std::string_view> find_embedded_shader(std::string_view name);
std::vector<std::string_view> embedded_shader_names();

namespace detail {
struct EmbeddedShader {
    std::string_view name;
    std::string_view source;  // NUL-terminated in storage: source.data()[source.size()] == '\0'
};
// The generated table, ended by an entry with an empty name.
extern const EmbeddedShader kEmbeddedShaders[];
}  // namespace detail

}  // namespace mvpl::gpu
