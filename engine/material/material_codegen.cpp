#include "engine/material/material_codegen.h"

#include <cstdio>
#include <map>
#include <stdexcept>

#include "engine/material/glsl_library.h"
#include "engine/material/graph_eval.h"

namespace mvpl::material {

void GlslModule::require(std::string_view name) {
    if (m_done.contains(name)) return;
    const GlslFunction* f = find_glsl_function(name);
    if (!f)
        throw std::logic_error("material codegen: no GLSL function '" + std::string(name) + "'");
    m_done.emplace(name);  // before the dependencies: the library has no cycles, but be safe
    for (const std::string_view dep : f->dependencies)
        require(dep);
    m_order.emplace_back(name);
}

std::string GlslModule::code() const {
    std::string out;
    for (const std::string& name : m_order) {
        const std::string_view code = find_glsl_function(name)->code;
        if (code.empty()) continue;
        out += code;
        out += '\n';
    }
    return out;
}

std::array<bool, kClosureTypeCount> possible_closure_types(NodeKind kind) {
    std::array<bool, kClosureTypeCount> t{};
    const auto set = [&](ClosureType c) { t[size_t(c)] = true; };
    switch (kind) {
        case NodeKind::Lambertian:
            set(ClosureType::Lambertian);
            break;
        case NodeKind::GgxConductor:
            set(ClosureType::Conductor);
            break;
        case NodeKind::DielectricDiffuse:
        case NodeKind::RoughDielectric:
            // A specular input that reaches 0 somewhere leaves the Lambertian base.
            set(ClosureType::Lambertian);
            set(ClosureType::Dielectric);
            break;
        default:
            t.fill(true);
    }
    return t;
}

std::string_view closure_eval_name(ClosureType type) {
    switch (type) {
        case ClosureType::Lambertian:
            return "lambertian_eval";
        case ClosureType::Conductor:
            return "ggx_conductor_eval";
        case ClosureType::Dielectric:
            return "dielectric_diffuse_eval";
        case ClosureType::MetalRough:
            return "metal_rough_eval";
    }
    return "metal_rough_eval";
}

std::array<bool, kClosureTypeCount> scene_closure_types(const std::vector<MaterialGraph>& graphs) {
    std::array<bool, kClosureTypeCount> t{};
    for (const MaterialGraph& g : graphs) {
        if (g.closure < 0) continue;
        const auto p = possible_closure_types(g.nodes[size_t(g.closure)].kind);
        for (int i = 0; i < kClosureTypeCount; ++i)
            t[size_t(i)] = t[size_t(i)] || p[size_t(i)];
    }
    if (graphs.empty()) t[size_t(ClosureType::Lambertian)] = true;
    return t;
}

std::string generate_closure_eval(const std::array<bool, kClosureTypeCount>& types,
                                  std::vector<std::string>* emitted) {
    GlslModule module;
    std::string dispatch =
        "// The closure types that occur in this scene (node_eval.h, ClosureType).\n"
        "vec3 closure_eval(Closure c, vec3 n, vec3 wo, vec3 wi) {\n";
    int last = -1;
    for (int i = 0; i < kClosureTypeCount; ++i)
        if (types[size_t(i)]) last = i;
    if (last < 0) last = 0;
    for (int i = 0; i <= last; ++i) {
        if (!types[size_t(i)] && i != last) continue;
        const std::string name(closure_eval_name(ClosureType(i)));
        module.require(name);
        if (i == last) {
            dispatch += "    return " + name + "(c, n, wo, wi);\n";
        } else {
            dispatch += "    if (c.type == " + std::to_string(i) + "u) return " + name +
                        "(c, n, wo, wi);\n";
        }
    }
    dispatch += "}\n";
    module.require("max_component");
    if (emitted) *emitted = module.functions();
    return module.code() + dispatch;
}

namespace {

std::string number(float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", double(v));
    std::string s(buf);
    if (s.find_first_of(".e") == std::string::npos) s += ".0";
    return s;
}

std::string vec(const Vec4& v) {
    return "vec4(" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + ", " + number(v.w) +
           ")";
}

std::string vec2(const Vec2& v) {
    return "vec2(" + number(v.x) + ", " + number(v.y) + ")";
}

int wrap_code(scene::Wrap w) {
    switch (w) {
        case scene::Wrap::Repeat:
            return 0;
        case scene::Wrap::ClampToEdge:
            return 1;
        case scene::Wrap::MirroredRepeat:
            return 2;
    }
    return 0;
}

bool reads_texture(const MaterialGraph& g, int index) {
    const Node& n = g.nodes.at(size_t(index));
    if (n.kind == NodeKind::ImageTexture) return true;
    for (const NodeInput& in : n.inputs) {
        if (in.node >= 0 && reads_texture(g, in.node)) return true;
    }
    return false;
}

class MaterialWriter {
public:
    MaterialWriter(GlslModule& module, const std::vector<scene::Texture>& textures,
                   std::map<int, int>& bindings, bool bind_textures)
        : m_module(module),
          m_textures(textures),
          m_bindings(bindings),
          m_bind_textures(bind_textures) {}

    // The vec4 expression of a node's value at the surface point `s`.
    std::string value(const MaterialGraph& g, int index, const std::string& s) {
        const Node& n = g.nodes.at(size_t(index));
        const auto in = [&](int k) { return input(g, n.inputs[size_t(k)], s); };
        switch (n.kind) {
            case NodeKind::Constant:
                return vec(n.value);
            case NodeKind::ImageTexture: {
                if (!n.texture.valid() || size_t(n.texture.texture) >= m_textures.size()) {
                    return vec(n.value);
                }
                if (!m_bind_textures) return "/* texture not bound */ " + vec(n.value);
                m_module.require("image_texture");
                const scene::Texture& t = m_textures[size_t(n.texture.texture)];
                const int slot = binding(n.texture.texture);
                return "image_texture(texture_" + std::to_string(slot) + ", " + s +
                       (n.texture.texcoord == 1 ? ".uv1" : ".uv0") + ", " + vec2(n.texture.offset) +
                       ", " + number(n.texture.rotation) + ", " + vec2(n.texture.scale) + ", " +
                       std::to_string(wrap_code(t.wrap_s)) + ", " +
                       std::to_string(wrap_code(t.wrap_t)) + ", " +
                       (t.filter == scene::Filter::Nearest ? "0" : "1") + ", " + vec(n.value) + ")";
            }
            case NodeKind::VertexColor:
                m_module.require("vertex_color");
                return "vertex_color(" + vec(n.value) + ", " + s + ".color)";
            case NodeKind::Mix:
                m_module.require("mix_node");
                return "mix_node(" + in(0) + ", " + in(1) + ", " + scalar(g, n.inputs[2], s) + ")";
            case NodeKind::Emission:
                m_module.require("emission");
                return "emission(" + in(0) + ", " + number(n.value.x) + ")";
            default:
                return "vec4(0.0)";
        }
    }

    // A scalar input as a float expression; constants as plain literals (readable code).
    std::string scalar(const MaterialGraph& g, const NodeInput& in, const std::string& s) {
        if (in.node < 0) return "0.0";
        const Node& n = g.nodes.at(size_t(in.node));
        if (n.kind == NodeKind::Constant) return number(n.value[in.channel < 0 ? 0 : in.channel]);
        return input(g, in, s) + ".x";
    }
    // An RGB input as a vec3 expression.
    std::string rgb(const MaterialGraph& g, const NodeInput& in, const std::string& s) {
        if (in.node >= 0 && g.nodes.at(size_t(in.node)).kind == NodeKind::Constant &&
            in.channel == kAllChannels) {
            const Vec4& v = g.nodes[size_t(in.node)].value;
            return "vec3(" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + ")";
        }
        return input(g, in, s) + ".rgb";
    }

    std::string input(const MaterialGraph& g, const NodeInput& in, const std::string& s) {
        if (in.node < 0) return "vec4(0.0)";
        const std::string v = value(g, in.node, s);
        if (in.channel == kAllChannels) return v;
        return "vec4(" + v + "." + "xyzw"[in.channel] + ")";
    }

    std::string closure(const MaterialGraph& g, const std::string& s) {
        if (g.closure < 0) {
            m_module.require("lambertian");
            return "lambertian(vec3(0.0))";
        }
        const Node& n = g.nodes[size_t(g.closure)];
        m_module.require(node_name(n.kind));
        const auto rgb = [&](int k) { return this->rgb(g, n.inputs[size_t(k)], s); };
        const auto x = [&](int k) { return scalar(g, n.inputs[size_t(k)], s); };
        std::string args;
        switch (n.kind) {
            case NodeKind::Lambertian:
                args = rgb(0);
                break;
            case NodeKind::GgxConductor:
                args = rgb(0) + ", " + x(1);
                break;
            case NodeKind::DielectricDiffuse:
                args = rgb(0) + ", " + x(1) + ", " + x(2) + ", " + rgb(3) + ", " + x(4);
                break;
            case NodeKind::MetalRough:
                args =
                    rgb(0) + ", " + x(1) + ", " + x(2) + ", " + x(3) + ", " + rgb(4) + ", " + x(5);
                break;
            case NodeKind::RoughDielectric:
                args = x(0) + ", " + x(1) + ", " + rgb(2) + ", " + x(3);
                break;
            default:
                args = "vec3(0.0)";
        }
        return std::string(node_name(n.kind)) + "(" + args + ")";
    }

    int binding(int texture) {
        const auto it = m_bindings.find(texture);
        if (it != m_bindings.end()) return it->second;
        const int slot = int(m_bindings.size());
        m_bindings.emplace(texture, slot);
        return slot;
    }

private:
    GlslModule& m_module;
    const std::vector<scene::Texture>& m_textures;
    std::map<int, int>& m_bindings;
    bool m_bind_textures;
};

}  // namespace

MaterialCode generate_material_code(const std::vector<MaterialGraph>& graphs,
                                    const std::vector<scene::Texture>& textures,
                                    uint32_t first_binding, bool bind_textures) {
    GlslModule module;
    module.require("Closure");
    module.require("SurfacePoint");
    std::map<int, int> bindings;
    MaterialWriter writer(module, textures, bindings, bind_textures);
    std::string materials;
    for (size_t i = 0; i < graphs.size(); ++i) {
        const MaterialGraph& g = graphs[i];
        const std::string name = "material_" + std::to_string(i);
        std::string body;
        body += "    c = " + writer.closure(g, "s") + ";\n";
        body += "    e = " +
                (g.emission >= 0 ? writer.value(g, g.emission, "s") + ".rgb" : "vec3(0.0)") + ";\n";
        std::string helper;
        if (g.normal < 0) {
            body += "    n = s.n;\n";
        } else if (!bind_textures && reads_texture(g, g.normal)) {
            // The interpolated normal stays: the pass that binds the textures maps it.
            body += "    n = s.n;  // normal from an unbound texture\n";
        } else {
            const Node& nn = g.nodes[size_t(g.normal)];
            module.require(node_name(nn.kind));
            if (nn.kind == NodeKind::NormalMap) {
                body += "    n = normal_map(" + writer.rgb(g, nn.inputs[0], "s") + ", " +
                        number(nn.value.x) + ", s);\n";
            } else {
                // The height at (u, v) and one step along u and v (graph_eval.cpp).
                const Vec2 step = bump_step(g, nn.inputs[0], textures);
                helper = "float " + name + "_height(SurfacePoint s) {\n    return " +
                         writer.scalar(g, nn.inputs[0], "s") + ";\n}\n";
                body += "    SurfacePoint su = s;\n    su.uv0.x += " + number(step.x) +
                        ";\n    su.uv1.x += " + number(step.x) + ";\n";
                body += "    SurfacePoint sv = s;\n    sv.uv0.y += " + number(step.y) +
                        ";\n    sv.uv1.y += " + number(step.y) + ";\n";
                body += "    n = bump_map(" + name + "_height(s), " + name + "_height(su), " +
                        name + "_height(sv), " + number(step.x) + ", " + number(step.y) + ", " +
                        number(nn.value.x) + ", s);\n";
            }
        }
        materials += "// " + name + "\n" + helper + "void " + name +
                     "(SurfacePoint s, out Closure c, out vec3 e, out vec3 n) {\n" + body + "}\n";
    }
    std::string dispatch =
        "void resolve_material(uint m, SurfacePoint s, out Closure c, out vec3 e, out vec3 n) {\n"
        "    switch (m) {\n";
    for (size_t i = 1; i < graphs.size(); ++i) {
        dispatch += "        case " + std::to_string(i) + "u: material_" + std::to_string(i) +
                    "(s, c, e, n); return;\n";
    }
    dispatch += "        default: " +
                std::string(graphs.empty() ? "c = lambertian(vec3(0.0)); e = vec3(0.0); n = s.n;"
                                           : "material_0(s, c, e, n);") +
                " return;\n    }\n}\n";
    if (graphs.empty()) module.require("lambertian");

    MaterialCode out;
    out.textures.resize(bindings.size());
    for (const auto& [texture, slot] : bindings) {
        out.textures[size_t(slot)] = texture;
        out.bindings +=
            "layout(set = 0, binding = " + std::to_string(first_binding + uint32_t(slot)) +
            ") uniform sampler2D texture_" + std::to_string(slot) + ";\n";
    }
    out.node_functions = module.functions();
    out.functions = module.code() + materials + dispatch;
    return out;
}

}  // namespace mvpl::material
