#pragma once
// One material graph written as GLSL expressions, for material_codegen.cpp: each node through its
// kind's glsl_call (node_kind.h), constants as literals, texture reads through the bindings handed
// out in first-use order. Private to engine/material.
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "engine/core/math.h"
#include "engine/material/glsl_literals.h"
#include "engine/material/graph_eval.h"
#include "engine/material/material_codegen.h"
#include "engine/material/node_graph.h"
#include "engine/material/node_kind.h"
#include "engine/scene/texture.h"

namespace mvpl::material {

// Writes the GLSL expressions of one material's graph; each node through its kind's glsl_call.
class MaterialWriter {
public:
    MaterialWriter(GlslModule& module, const std::vector<scene::Texture>& textures,
                   std::map<int, int>& bindings, bool bind_textures)
        : m_module(module),
          m_textures(textures),
          m_bindings(bindings),
          m_bind_textures(bind_textures) {}

    // Starts the material `name`: helper functions are named after it.
    void begin(const MaterialGraph& g, const std::string& name) {
        m_graph = &g;
        m_name = name;
        m_helpers.clear();
        m_function_count = 0;
    }
    // The helper functions written since begin(), to precede the material's function.
    const std::string& helpers() const { return m_helpers; }

    // The expression of node `index`'s output (a vec4 for value nodes).
    std::string node(int index);
    // An input as a vec4 expression.
    std::string input(const NodeInput& in) {
        if (in.node < 0) return "vec4(0.0)";
        const std::string v = value(in.node);
        if (in.channel == kAllChannels) return v;
        return "vec4(" + v + "." + "xyzw"[in.channel] + ")";
    }
    // A scalar input as a float expression; constants as plain literals (readable code).
    std::string scalar(const NodeInput& in) {
        if (in.node < 0) return "0.0";
        const Node& n = m_graph->nodes.at(size_t(in.node));
        if (n.kind == &node_kind("constant"))
            return glsl_number(n.value[in.channel < 0 ? 0 : in.channel]);
        return input(in) + ".x";
    }
    // An RGB input as a vec3 expression.
    std::string rgb(const NodeInput& in) {
        if (in.node >= 0 && m_graph->nodes.at(size_t(in.node)).kind == &node_kind("constant") &&
            in.channel == kAllChannels) {
            const Vec4& v = m_graph->nodes[size_t(in.node)].value;
            return "vec3(" + glsl_number(v.x) + ", " + glsl_number(v.y) + ", " + glsl_number(v.z) +
                   ")";
        }
        return input(in) + ".rgb";
    }
    // A generated `float f(SurfacePoint s)` returning the input's x.
    std::string scalar_function(const NodeInput& in) {
        const std::string name = m_name + "_f" + std::to_string(m_function_count++);
        const std::string body = scalar(in);
        m_helpers += "float " + name + "(SurfacePoint s) {\n    return " + body + ";\n}\n";
        return name;
    }
    Vec2 texel_step(const NodeInput& in) const { return bump_step(*m_graph, in, m_textures); }
    const scene::Texture* texture(const scene::TextureRef& ref) const {
        if (!ref.valid() || size_t(ref.texture) >= m_textures.size()) return nullptr;
        return &m_textures[size_t(ref.texture)];
    }
    std::string sampler(const scene::TextureRef& ref) {
        if (!m_bind_textures) return "";
        return "texture_" + std::to_string(binding(ref.texture));
    }
    void require(std::string_view function) { m_module.require(function); }
    const MaterialGraph& graph() const { return *m_graph; }

private:
    std::string value(int index) {
        if (!m_graph->nodes.at(size_t(index)).kind->value) return "vec4(0.0)";
        return node(index);
    }
    int binding(int texture) {
        const auto it = m_bindings.find(texture);
        if (it != m_bindings.end()) return it->second;
        const int slot = int(m_bindings.size());
        m_bindings.emplace(texture, slot);
        return slot;
    }

    GlslModule& m_module;
    const std::vector<scene::Texture>& m_textures;
    std::map<int, int>& m_bindings;
    bool m_bind_textures;
    const MaterialGraph* m_graph = nullptr;
    std::string m_name;
    std::string m_helpers;
    int m_function_count = 0;
};

}  // namespace mvpl::material
