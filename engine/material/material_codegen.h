#pragma once
// GLSL generation from material graphs (docs/design.md, "Shader chain"): walks the scene's graphs,
// emits each function they need once, dependencies first, then one function per material that
// resolves its graph at a surface point, and the closure-evaluation dispatch that contains only
// the closure types that occur.
#include <array>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "engine/material/node_graph.h"

namespace mvpl::material {

// Functions of glsl_library.h, each once, dependencies before their users.
class GlslModule {
public:
    // Throws std::logic_error for an unknown name (a bug in a generator, not an input error).
    void require(std::string_view name);
    const std::vector<std::string>& functions() const { return m_order; }
    std::string code() const;

private:
    std::set<std::string, std::less<>> m_done;
    std::vector<std::string> m_order;
};

// The closure types a closure node kind can produce at run time (NodeKind::closure_types).
std::array<bool, kClosureTypeCount> possible_closure_types(const NodeKind& kind);
std::string_view closure_eval_name(ClosureType type);

struct MaterialCode {
    // Declarations of the texture bindings the graphs read ("uniform sampler2D texture_N",
    // binding first_binding + position in `textures`), empty without textures.
    std::string bindings;
    // The node functions and `void material_N(SurfacePoint s, out Closure c, out vec3 e,
    // out vec3 n)` for every distinct used material, then `resolve_material(uint m, …)`.
    std::string functions;
    std::vector<int> textures;                // scene texture indices, in binding order
    std::vector<std::string> node_functions;  // what `functions` emitted, in order
    // A used graph is alpha-tested (glTF alphaMode MASK or BLEND): `functions` ends with
    // `bool alpha_cut(uint m, SurfacePoint s, vec3 p, uint seed)`, true where material m cuts
    // its surface at s: MASK where the base alpha is below alphaCutoff, BLEND (hashed
    // transparency) where alpha_hash(p, seed) ≥ alpha. Other scenes get no such function.
    bool alpha_tested = false;
};

// GLSL for the G-buffer. first_binding: the binding of the first texture. bind_textures false:
// image textures read as their factor alone (for a pipeline that has no texture bindings).
// used (empty: all): the materials that something is drawn with; the others get no code, their
// index the default branch. Materials whose code is the same share one function, named
// material_I after the first of them (I its index), so that code grows with the distinct
// materials a scene draws, not with the materials it lists.
MaterialCode generate_material_code(const std::vector<MaterialGraph>& graphs,
                                    const std::vector<scene::Texture>& textures,
                                    uint32_t first_binding, bool bind_textures = true,
                                    const std::vector<bool>& used = {});

// `vec3 closure_eval(Closure c, vec3 n, vec3 wo, vec3 wi)` with a branch per present type, and
// the functions it needs.
std::string generate_closure_eval(const std::array<bool, kClosureTypeCount>& types,
                                  std::vector<std::string>* emitted = nullptr);

// The union of possible_closure_types over the graphs' closure nodes.
std::array<bool, kClosureTypeCount> scene_closure_types(const std::vector<MaterialGraph>& graphs);

}  // namespace mvpl::material
