#include "engine/material/material_codegen.h"

#include <algorithm>
#include <map>
#include <stdexcept>

#include "engine/material/glsl_library.h"
#include "engine/material/graph_eval.h"
#include "engine/material/material_writer.h"

namespace mvpl::material {

namespace {
constexpr size_t kDispatchGroup = 32;
}  // namespace

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

std::array<bool, kClosureTypeCount> possible_closure_types(const NodeKind& kind) {
    std::array<bool, kClosureTypeCount> t{};
    for (int i = 0; i < kClosureTypeCount; ++i)
        t[size_t(i)] = (kind.closure_types & closure_type_bit(ClosureType(i))) != 0;
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
        const auto p = possible_closure_types(*g.nodes[size_t(g.closure)].kind);
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
        "// The closure types that occur in this scene (closure.h, ClosureType).\n"
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
    // With a glossy type: the diffuse lobe alone (Bsdf::eval_diffuse), for the lobe-wise clamp
    // of the shading pass. A Lambertian-only scene's code stays as it was.
    if (last > 0) {
        module.require("metal_rough_diffuse_eval");
        dispatch +=
            "// The diffuse lobe of closure_eval alone (Bsdf::eval_diffuse).\n"
            "vec3 closure_eval_diffuse(Closure c, vec3 n, vec3 wo, vec3 wi) {\n";
        if (types[size_t(ClosureType::Conductor)])
            dispatch += "    if (c.type == 1u) return vec3(0.0);\n";
        dispatch += "    return metal_rough_diffuse_eval(c, n, wo, wi);\n}\n";
    }
    module.require("max_component");
    if (emitted) *emitted = module.functions();
    return module.code() + dispatch;
}

namespace {

bool reads_texture(const MaterialGraph& g, int index) {
    const Node& n = g.nodes.at(size_t(index));
    if (n.texture.valid()) return true;
    for (const NodeInput& in : n.inputs) {
        if (in.node >= 0 && reads_texture(g, in.node)) return true;
    }
    return false;
}

bool is_used(const std::vector<bool>& used, size_t i) {
    return used.empty() || (i < used.size() && used[i]);
}

// The statements of graph g's material function: its closure c, emission e and normal n.
std::string material_body(MaterialWriter& writer, GlslModule& module, const MaterialGraph& g,
                          bool bind_textures) {
    std::string body;
    if (g.closure >= 0 && g.nodes[size_t(g.closure)].kind->closure) {
        body += "    c = " + writer.node(g.closure) + ";\n";
    } else {
        module.require("lambertian");
        body += "    c = lambertian(vec3(0.0));\n";
    }
    body += "    e = " + (g.emission >= 0 ? writer.node(g.emission) + ".rgb" : "vec3(0.0)") + ";\n";
    if (g.normal < 0 || !g.nodes[size_t(g.normal)].kind->normal) {
        body += "    n = s.n;\n";
    } else if (!bind_textures && reads_texture(g, g.normal)) {
        // The interpolated normal stays: the pass that binds the textures maps it.
        body += "    n = s.n;  // normal from an unbound texture\n";
    } else {
        body += "    n = " + writer.node(g.normal) + ";\n";
    }
    return body;
}

// The distinct material functions and which material calls which.
struct MaterialFunctions {
    std::vector<std::string> bodies;  // with the placeholder, one per distinct function
    std::vector<size_t> first_of;     // the first material of each distinct function
    std::vector<int> function_of;     // per material, -1 where unused
    std::string code;                 // the functions, each named after its first material

    std::string name(int f) const { return "material_" + std::to_string(first_of[size_t(f)]); }
};

MaterialFunctions write_materials(MaterialWriter& writer, GlslModule& module,
                                  const std::vector<MaterialGraph>& graphs, bool bind_textures,
                                  const std::vector<bool>& used) {
    // Written with a placeholder name so that materials whose code is the same share one
    // function (real models repeat materials), which is then named after its first material.
    const std::string placeholder = "material_@";
    MaterialFunctions out;
    out.function_of.assign(graphs.size(), -1);
    for (size_t i = 0; i < graphs.size(); ++i) {
        if (!is_used(used, i)) continue;
        const MaterialGraph& g = graphs[i];
        writer.begin(g, placeholder);
        const std::string body = material_body(writer, module, g, bind_textures);
        const std::string code = writer.helpers() + "void " + placeholder +
                                 "(SurfacePoint s, out Closure c, out vec3 e, out vec3 n) {\n" +
                                 body + "}\n";
        const auto same = std::find(out.bodies.begin(), out.bodies.end(), code);
        if (same != out.bodies.end()) {
            out.function_of[i] = int(same - out.bodies.begin());
            continue;
        }
        out.function_of[i] = int(out.bodies.size());
        out.bodies.push_back(code);
        out.first_of.push_back(i);
        const std::string name = "material_" + std::to_string(i);
        std::string named = code;
        for (size_t at = named.find(placeholder); at != std::string::npos;
             at = named.find(placeholder, at + name.size()))
            named.replace(at, placeholder.size(), name);
        out.code += "// " + name + "\n" + named;
    }
    return out;
}

// resolve_material(m, ...): calls material m's function.
std::string dispatch_code(const MaterialFunctions& functions, size_t material_count) {
    // Materials that share the default's function, and unused ones, take the default branch.
    const int fallback = functions.bodies.empty() ? -1 : 0;
    // Two levels of switch, kDispatchGroup cases each at most: lavapipe (Mesa 22.3) mis-shades
    // a switch of about 80 cases or more (tests/render/test_many_materials.cpp: with 100
    // materials in one switch, the first 21 resolved black; as one if-chain, the last 20).
    const std::string fallback_call =
        fallback < 0 ? std::string("c = lambertian(vec3(0.0)); e = vec3(0.0); n = s.n;")
                     : functions.name(fallback) + "(s, c, e, n);";
    std::string groups;
    std::string top =
        "void resolve_material(uint m, SurfacePoint s, out Closure c, out vec3 e, out vec3 n) {\n"
        "    switch (m / " +
        std::to_string(kDispatchGroup) + "u) {\n";
    for (size_t g0 = 0; g0 < material_count; g0 += kDispatchGroup) {
        std::string cases;
        for (size_t i = g0; i < std::min(material_count, g0 + kDispatchGroup); ++i) {
            const int f = functions.function_of[i];
            if (f < 0 || f == fallback) continue;
            cases += "        case " + std::to_string(i) + "u: " + functions.name(f) +
                     "(s, c, e, n); return;\n";
        }
        if (cases.empty()) continue;
        const std::string name = "resolve_group_" + std::to_string(g0 / kDispatchGroup);
        groups += "void " + name +
                  "(uint m, SurfacePoint s, out Closure c, out vec3 e, out vec3 n) {\n"
                  "    switch (m) {\n" +
                  cases + "        default: " + fallback_call + " return;\n    }\n}\n";
        top += "        case " + std::to_string(g0 / kDispatchGroup) + "u: " + name +
               "(m, s, c, e, n); return;\n";
    }
    return groups + top + "        default: " + fallback_call + " return;\n    }\n}\n";
}

// The alpha-tested materials' helpers and their cases of alpha_cut.
struct AlphaCode {
    std::string helpers;
    std::string cases;
};

AlphaCode alpha_code(MaterialWriter& writer, GlslModule& module,
                     const std::vector<MaterialGraph>& graphs, const std::vector<bool>& used) {
    AlphaCode out;
    for (size_t i = 0; i < graphs.size(); ++i) {
        if (!is_used(used, i)) continue;
        const MaterialGraph& g = graphs[i];
        if (!g.alpha_tested()) continue;
        writer.begin(g, "alpha_" + std::to_string(i));
        const std::string alpha = writer.scalar(g.alpha);
        out.helpers += writer.helpers();
        if (g.masked()) {
            out.cases += "        case " + std::to_string(i) + "u: return " + alpha + " < " +
                         glsl_number(g.alpha_cutoff) + ";\n";
        } else {
            module.require("alpha_hash");
            out.cases += "        case " + std::to_string(i) +
                         "u: return alpha_hash(p, seed) >= " + alpha + ";\n";
        }
    }
    return out;
}

}  // namespace

MaterialCode generate_material_code(const std::vector<MaterialGraph>& graphs,
                                    const std::vector<scene::Texture>& textures,
                                    uint32_t first_binding, bool bind_textures,
                                    const std::vector<bool>& used) {
    GlslModule module;
    module.require("Closure");
    module.require("SurfacePoint");
    std::map<int, int> bindings;
    MaterialWriter writer(module, textures, bindings, bind_textures);
    const MaterialFunctions functions =
        write_materials(writer, module, graphs, bind_textures, used);
    const std::string dispatch = dispatch_code(functions, graphs.size());
    if (functions.bodies.empty()) module.require("lambertian");
    const AlphaCode alpha = alpha_code(writer, module, graphs, used);

    MaterialCode out;
    out.textures.resize(bindings.size());
    for (const auto& [texture, slot] : bindings) {
        out.textures[size_t(slot)] = texture;
        out.bindings +=
            "layout(set = 0, binding = " + std::to_string(first_binding + uint32_t(slot)) +
            ") uniform sampler2D texture_" + std::to_string(slot) + ";\n";
    }
    out.node_functions = module.functions();
    out.functions = module.code() + functions.code + dispatch;
    if (!alpha.cases.empty()) {
        out.alpha_tested = true;
        out.functions += alpha.helpers +
                         "// glTF alphaMode MASK or BLEND: whether material m cuts its surface at "
                         "s (at p).\n"
                         "bool alpha_cut(uint m, SurfacePoint s, vec3 p, uint seed) {\n"
                         "    switch (m) {\n" +
                         alpha.cases + "        default: return false;\n    }\n}\n";
    }
    return out;
}

}  // namespace mvpl::material
