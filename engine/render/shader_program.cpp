#include "engine/render/shader_program.h"

#include "engine/material/scene_materials.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "engine/core/error.h"
#include "engine/gpu/embedded_shaders.h"
#include "engine/gpu/gpu_error.h"
#include "engine/material/material_codegen.h"
#include "engine/render/closed_surface.h"

namespace mvpl::render {
namespace {

const char* const kVplTypeNames[kVplTypeCount] = {"point", "spot", "area", "surface",
                                                  "directional"};

std::string trim(std::string_view s) {
    const size_t a = s.find_first_not_of(" \t\r");
    if (a == std::string_view::npos) return {};
    const size_t b = s.find_last_not_of(" \t\r");
    return std::string(s.substr(a, b - a + 1));
}

// `//@if a|b|!c`: a or b enabled, or c not.
bool any_enabled(const std::string& names, const std::vector<std::string>& enabled) {
    std::istringstream in(names);
    std::string name;
    while (std::getline(in, name, '|')) {
        std::string n = trim(name);
        const bool negated = n.starts_with("!");
        if (negated) n = trim(std::string_view(n).substr(1));
        if ((std::find(enabled.begin(), enabled.end(), n) != enabled.end()) != negated) return true;
    }
    return false;
}

std::vector<std::string> enabled_names(const ShaderFeatures& f) {
    std::vector<std::string> out;
    for (int i = 0; i < kVplTypeCount; ++i)
        if (f.vpl_types[size_t(i)]) out.emplace_back(kVplTypeNames[i]);
    if (f.thin_walls) out.emplace_back("thin_walls");
    if (f.specular_chains) out.emplace_back("specular_chains");
    if (f.glossy()) out.emplace_back("glossy");
    return out;
}

// `#include "x"` as glslang's includer resolves it (engine/gpu/shader_compiler.cpp): next to the
// including file (dir), then from shaders/. Returns the embedded name.
std::string resolve_include(const std::string& dir, const std::string& file) {
    if (gpu::find_embedded_shader(dir + file)) return dir + file;
    if (gpu::find_embedded_shader(file)) return file;
    throw gpu::GpuError("shader template: cannot find '" + file + "' included from " +
                        (dir.empty() ? std::string("shaders/") : dir));
}

// An open #if/#ifdef/#ifndef of the file being expanded. The C++ side of a shared header
// (shaders/shared/prelude.h: `#ifdef __cplusplus` … `#else` … `#endif`) is left out here, so that
// a stage holds GLSL only (no <cstdint>, no templates); other conditionals are glslang's.
struct Conditional {
    bool cplusplus;  // tests __cplusplus
    bool in_cxx;     // … and the lines now are its C++ branch
};

// Handles a preprocessor conditional line t; true when the line is consumed (not to be emitted).
// *drop: whether the lines that follow belong to a C++ branch.
bool conditional_line(const std::string& t, std::vector<Conditional>& open, bool* drop) {
    if (!t.starts_with("#")) return false;
    std::istringstream words(t.substr(1));
    std::string directive;
    std::string argument;
    words >> directive >> argument;
    bool consumed = false;
    if (directive == "ifdef" || directive == "ifndef" || directive == "if") {
        const bool cplusplus = directive != "if" && argument == "__cplusplus";
        open.push_back({cplusplus, cplusplus && directive == "ifdef"});
        consumed = cplusplus;
    } else if (!open.empty() && (directive == "else" || directive == "elif")) {
        if (open.back().cplusplus && directive == "elif")
            throw gpu::GpuError("shader template: #elif after #ifdef __cplusplus");
        if (open.back().cplusplus) open.back().in_cxx = !open.back().in_cxx;
        consumed = open.back().cplusplus;
    } else if (!open.empty() && directive == "endif") {
        consumed = open.back().cplusplus;
        open.pop_back();
    } else {
        return false;
    }
    *drop = std::any_of(open.begin(), open.end(),
                        [](const Conditional& c) { return c.cplusplus && c.in_cxx; });
    return consumed;
}

// dir: the including file's directory ("render/"); included: the files already expanded, each
// inlined once (their include guards would drop a repeat anyway; this keeps dumps short).
std::string expand(std::string_view text, const std::string& dir,
                   const std::vector<std::string>& enabled,
                   const std::vector<std::pair<std::string, std::string>>& inserts,
                   std::vector<std::string>& included) {
    std::istringstream in{std::string(text)};
    std::string out;
    std::string line;
    std::vector<bool> keep{true};
    std::vector<Conditional> conditionals;
    bool cxx = false;  // in the C++ branch of a shared header
    while (std::getline(in, line)) {
        const std::string t = trim(line);
        if (t.starts_with("//@if ")) {
            keep.push_back(keep.back() && any_enabled(t.substr(6), enabled));
            continue;
        }
        if (t == "//@endif") {
            if (keep.size() > 1) keep.pop_back();
            continue;
        }
        if (!keep.back()) continue;
        const bool was_cxx = cxx;
        if (conditional_line(t, conditionals, &cxx) || was_cxx) continue;
        if (t.starts_with("//@insert ")) {
            const std::string name = trim(t.substr(10));
            const auto it = std::find_if(inserts.begin(), inserts.end(),
                                         [&](const auto& kv) { return kv.first == name; });
            if (it == inserts.end())
                throw gpu::GpuError("shader template: nothing to insert for '" + name + "'");
            // Generated code holds shared headers' text too (material/glsl_library.cpp): expanded
            // as they are when included, without their C++ branches.
            out += expand(it->second, dir, enabled, {}, included);
            continue;
        }
        if (t.starts_with("#extension GL_GOOGLE_include_directive")) continue;
        if (t.starts_with("#include \"")) {
            const std::string name = resolve_include(dir, t.substr(10, t.size() - 11));
            if (std::find(included.begin(), included.end(), name) != included.end()) continue;
            included.push_back(name);
            out += expand(gpu::embedded_shader(name), name.substr(0, name.rfind('/') + 1), enabled,
                          inserts, included);
            continue;
        }
        out += line;
        out += '\n';
    }
    return out;
}

}  // namespace

std::string expand_template(std::string_view text, const std::vector<std::string>& enabled,
                            const std::vector<std::pair<std::string, std::string>>& inserts) {
    std::vector<std::string> included;
    return expand(text, "render/", enabled, inserts, included);
}

ShaderFeatures ShaderFeatures::all() {
    ShaderFeatures f;
    f.vpl_types.fill(true);
    f.closure_types.fill(true);
    f.thin_walls = true;
    return f;
}

ShaderFeatures scene_features(const scene::Scene& scene, const ShaderOptions& options) {
    ShaderFeatures f;
    for (const scene::Light& l : scene.lights) {
        switch (l.type) {
            case scene::LightType::Point:
                f.vpl_types[size_t(light::VplType::Point)] = true;
                break;
            case scene::LightType::Spot:
                f.vpl_types[size_t(light::VplType::Spot)] = true;
                break;
            case scene::LightType::Directional:
                f.vpl_types[size_t(light::VplType::Directional)] = true;
                break;
        }
    }
    for (const scene::Mesh& m : scene.meshes) {
        if (m.material >= 0 && size_t(m.material) < scene.materials.size() &&
            scene.materials[size_t(m.material)].is_emissive() && m.triangle_count() > 0) {
            f.vpl_types[size_t(light::VplType::Area)] = true;
        }
    }
    f.vpl_types[size_t(light::VplType::Surface)] = options.surface_vpls;
    // The environment's direct light comes as directional VPLs (light::LightSampler::sample_le).
    if (scene.environment.active()) f.vpl_types[size_t(light::VplType::Directional)] = true;
    const material::SceneMaterials materials(scene);
    const std::vector<bool> drawn = scene.drawn_materials();
    std::vector<material::MaterialGraph> graphs;
    for (size_t i = 0; i < drawn.size(); ++i) {
        if (!drawn[i]) continue;
        graphs.push_back(materials.graph(int(i)));
        f.thin_walls = f.thin_walls || graphs.back().double_sided;
    }
    // A one-sided open surface is a zero-thickness occluder too: light transport keeps its back
    // faces (README, "Conventions"), so a wall of one plane leaks at its junctions as a
    // double-sided one does (tests/render/test_thin_walls.cpp). Only closed solids cannot.
    for (const scene::Mesh& m : scene.meshes) {
        if (f.thin_walls) break;
        f.thin_walls = m.triangle_count() > 0 && !bounds_solid(m);
    }
    f.closure_types = material::scene_closure_types(graphs);
    return f;
}

StageSource generate_shading_source(const ShaderFeatures& features,
                                    std::vector<std::string>* functions) {
    const std::string closures = material::generate_closure_eval(features.closure_types, functions);
    return {"shading.comp", expand_template(gpu::embedded_shader("render/shading_template.glsl"),
                                            enabled_names(features), {{"closures", closures}})};
}

StageSource generate_matrix_source(const ShaderFeatures& features) {
    ShaderFeatures f = features;
    f.specular_chains = false;  // a row is its chain's end already (matrix_template.glsl)
    const std::string closures = material::generate_closure_eval(f.closure_types, nullptr);
    return {"matrix.comp", expand_template(gpu::embedded_shader("render/matrix_template.glsl"),
                                           enabled_names(f), {{"closures", closures}})};
}

GBufferSources generate_g_buffer_sources(const std::vector<material::MaterialGraph>& graphs,
                                         const std::vector<scene::Texture>& textures,
                                         const std::vector<bool>& drawn) {
    // Image textures read as their factors in the G-buffer's fragment stage, and the material
    // pass applies them, unless a drawn material is masked: then the fragment stage binds the
    // textures, as its alpha test needs them (and the material pass repeats what it resolved).
    const bool masked = std::any_of(graphs.begin(), graphs.end(), [&](const auto& g) {
        const size_t i = size_t(&g - graphs.data());
        return g.alpha_tested() && (drawn.empty() || (i < drawn.size() && drawn[i]));
    });
    const material::MaterialCode code =
        material::generate_material_code(graphs, textures, 0, masked, drawn);
    GBufferSources out;
    out.alpha_tested = code.alpha_tested;
    out.fragment_textures = code.textures;
    const material::MaterialCode textured =
        material::generate_material_code(graphs, textures, 1, true, drawn);
    out.color_handoff = !textured.textures.empty() &&
                        std::find(textured.node_functions.begin(), textured.node_functions.end(),
                                  "vertex_color") != textured.node_functions.end();
    std::vector<std::string> enabled;
    if (out.color_handoff) enabled.emplace_back("color_handoff");
    if (out.alpha_tested) enabled.emplace_back("alpha_tested");
    out.functions = code.node_functions;
    const std::string push =
        expand_template(gpu::embedded_shader("render/g_buffer_push.glsl"), {}, {});
    out.vert = {"g_buffer.vert",
                expand_template(gpu::embedded_shader("render/g_buffer.vert"), {}, {})};
    out.frag = {"g_buffer.frag",
                expand_template(
                    gpu::embedded_shader("render/g_buffer.frag"), enabled,
                    {{"push", push}, {"bindings", code.bindings}, {"materials", code.functions}})};
    if (!textured.textures.empty()) {
        out.textures = textured.textures;
        out.material_functions = textured.node_functions;
        out.material = {
            "material.comp",
            expand_template(gpu::embedded_shader("render/material_template.glsl"), enabled,
                            {{"bindings", textured.bindings}, {"materials", textured.functions}})};
    }
    return out;
}

ShadowAlphaSources generate_shadow_alpha_sources(const std::vector<material::MaterialGraph>& graphs,
                                                 const std::vector<scene::Texture>& textures,
                                                 const std::vector<bool>& drawn) {
    std::vector<bool> tested(graphs.size(), false);
    for (size_t i = 0; i < graphs.size(); ++i)
        tested[i] = graphs[i].alpha_tested() && (drawn.empty() || (i < drawn.size() && drawn[i]));
    ShadowAlphaSources out;
    if (std::find(tested.begin(), tested.end(), true) == tested.end()) return out;
    // Code for those materials only: their alpha_cut, with their textures bound.
    const material::MaterialCode code =
        material::generate_material_code(graphs, textures, 0, true, tested);
    out.textures = code.textures;
    out.frag = {"shadow_masked.frag",
                expand_template(gpu::embedded_shader("render/shadow_masked.frag"), {},
                                {{"bindings", code.bindings}, {"materials", code.functions}})};
    return out;
}

SceneShaders generate_scene_shaders(const scene::Scene& scene, const ShaderOptions& options) {
    SceneShaders out;
    out.features = scene_features(scene, options);
    const material::SceneMaterials materials(scene);
    GBufferSources g =
        generate_g_buffer_sources(materials.graphs(), scene.textures, scene.drawn_materials());
    out.g_buffer_vert = std::move(g.vert);
    out.g_buffer_frag = std::move(g.frag);
    out.g_buffer_functions = std::move(g.functions);
    out.material_comp = std::move(g.material);
    out.material_functions = std::move(g.material_functions);
    out.shading_comp = generate_shading_source(out.features, &out.shading_functions);
    return out;
}

void dump_shaders(const std::string& dir, const std::vector<const StageSource*>& stages) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw InputError(dir, "cannot create the shader dump directory: " + ec.message());
    for (const StageSource* stage : stages) {
        const std::filesystem::path path = std::filesystem::path(dir) / stage->name;
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out << stage->source;
        if (!out.flush()) throw InputError(path.string(), "cannot write the generated shader");
    }
}

}  // namespace mvpl::render
