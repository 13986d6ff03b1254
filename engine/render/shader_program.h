#pragma once
// The GLSL of every stage, generated for one scene (docs/design.md, "Shader chain"): the scene's
// material graphs resolved in the G-buffer fragment shader, and a shading shader with only the
// closure types and VPL types the scene can produce. Vulkan-free.
#include <array>
#include <string>
#include <vector>

#include "engine/light/vpl.h"
#include "engine/material/closure.h"
#include "engine/material/node_graph.h"
#include "engine/scene/scene.h"

namespace mvpl::render {

inline constexpr int kVplTypeCount = 5;

struct ShaderFeatures {
    std::array<bool, kVplTypeCount> vpl_types{};  // indexed by light::VplType
    std::array<bool, material::kClosureTypeCount> closure_types{};
    // A drawn material is double-sided or a mesh is open (not a solid: closed_surface.h), so the
    // scene may hold zero-thickness walls: the shadow test adds its junction lookup
    // (shaders/render/shadow_lookup.glsl, visibility()).
    bool thin_walls = false;
    // Glossy pixels are shaded at the end of their specular chains (engine/render/chain_layer.h):
    // the shading pass reads the chain records (binding 5). Not in all(): it needs the layer.
    bool specular_chains = false;

    bool has(light::VplType t) const { return vpl_types[size_t(t)]; }
    // Some closure type with a microfacet lobe: area and surface VPLs are shaded as virtual
    // spherical lights (shaders/shared/virtual_sphere.h); a diffuse-only scene's shader has no
    // such code.
    bool glossy() const {
        for (size_t i = 1; i < closure_types.size(); ++i)
            if (closure_types[i]) return true;
        return false;
    }
    bool has_directional() const { return has(light::VplType::Directional); }
    // Every VPL and closure type: for callers that shade VPLs of unknown origin (tests).
    static ShaderFeatures all();
};

struct ShaderOptions {
    // Surface VPLs (path length ≥ 1) exist when the sampler's maximum depth is ≥ 3.
    bool surface_vpls = true;
};

// What a scene can produce: point/spot/directional VPLs from its punctual lights, area VPLs if
// a mesh uses an emissive material, surface VPLs if options.surface_vpls; the closure types of
// the material graphs it draws with.
ShaderFeatures scene_features(const scene::Scene& scene, const ShaderOptions& options);

struct StageSource {
    std::string name;    // "g_buffer.vert", "g_buffer.frag", "shading.comp"
    std::string source;  // self-contained GLSL (no #include)
};

struct SceneShaders {
    ShaderFeatures features;
    StageSource g_buffer_vert;
    StageSource g_buffer_frag;
    StageSource shading_comp;
    StageSource material_comp;                    // empty name: the scene needs no material pass
    std::vector<std::string> g_buffer_functions;  // node functions, in emission order
    std::vector<std::string> material_functions;
    std::vector<std::string> shading_functions;

    std::vector<const StageSource*> stages() const {
        std::vector<const StageSource*> out{&g_buffer_vert, &g_buffer_frag, &shading_comp};
        if (!material_comp.name.empty()) out.push_back(&material_comp);
        return out;
    }
};

SceneShaders generate_scene_shaders(const scene::Scene& scene, const ShaderOptions& options);

struct GBufferSources {
    StageSource vert;
    StageSource frag;
    std::vector<std::string> functions;  // node functions of the fragment stage, in order
    // The material pass (material_template.glsl), only when a graph reads an image texture:
    // binding 0 the G-buffer, binding 1 + i the scene texture textures[i].
    StageSource material;
    std::vector<int> textures;
    std::vector<std::string> material_functions;
    // Scenes that draw an alpha-tested material (glTF alphaMode MASK or BLEND): the fragment
    // stage binds these scene textures (binding i: textures[i]) to test alpha, and discards
    // what is cut.
    std::vector<int> fragment_textures;
    bool alpha_tested = false;
    // The fragment stage hands COLOR_0 to the material pass in the specular layer (which that
    // pass rewrites): a drawn graph reads vertex colours and the scene has a material pass.
    bool color_handoff = false;
    bool has_material_pass() const { return !textures.empty(); }
};
// The G-buffer stages for material graphs (textures: the scene's, for the bump-map step; drawn:
// Scene::drawn_materials, empty for all).
GBufferSources generate_g_buffer_sources(const std::vector<material::MaterialGraph>& graphs,
                                         const std::vector<scene::Texture>& textures,
                                         const std::vector<bool>& drawn = {});
// The fragment stage of the shadow maps' alpha-tested draws (shadow_masked.frag): alpha_cut for
// the drawn materials that glTF MASK or BLEND makes alpha-tested, with their textures.
struct ShadowAlphaSources {
    StageSource frag;           // "shadow_masked.frag"; empty name: no such material is drawn
    std::vector<int> textures;  // binding i: the scene texture textures[i]
};
ShadowAlphaSources generate_shadow_alpha_sources(const std::vector<material::MaterialGraph>& graphs,
                                                 const std::vector<scene::Texture>& textures,
                                                 const std::vector<bool>& drawn = {});

// The shading shader for `features`.
StageSource generate_shading_source(const ShaderFeatures& features,
                                    std::vector<std::string>* functions = nullptr);

// The reduced matrix's shader (matrix_template.glsl, matrix_pass.h) for `features`.
StageSource generate_matrix_source(const ShaderFeatures& features);

// Writes each stage to dir/NAME (creating dir); throws InputError naming the path on failure.
void dump_shaders(const std::string& dir, const std::vector<const StageSource*>& stages);

// Expands the template markers of shaders/render (`//@insert NAME`, `//@if a|b` … `//@endif`)
// and `#include "x"` of embedded shaders (each inlined once, found next to the includer, then
// from shaders/: "shared/gpu_vpl.h"), so that a stage's source, and the SPIR-V cache's hash of
// it, holds everything it is compiled from. Exposed for tests.
std::string expand_template(std::string_view text, const std::vector<std::string>& enabled,
                            const std::vector<std::pair<std::string, std::string>>& inserts);

}  // namespace mvpl::render
