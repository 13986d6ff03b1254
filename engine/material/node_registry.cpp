// The node kinds by name: one line a kind, each defined in nodes/<name>.cpp.
#include <stdexcept>
#include <string>

#include "engine/material/node_kind.h"

// X(Name): nodes/<name>.cpp defines mvpl::material::nodes::k<Name>Node.
#define MVPL_NODE_KINDS(X) \
    X(Constant)            \
    X(ImageTexture)        \
    X(VertexColor)         \
    X(Mix)                 \
    X(Multiply)            \
    X(Emission)            \
    X(NormalMap)           \
    X(BumpMap)             \
    X(Lambertian)          \
    X(GgxConductor)        \
    X(DielectricDiffuse)   \
    X(MetalRough)          \
    X(RoughDielectric)     \
    X(SpecGloss)

namespace mvpl::material {
namespace nodes {
#define MVPL_DECLARE_NODE_KIND(Name) extern const NodeKind k##Name##Node;
MVPL_NODE_KINDS(MVPL_DECLARE_NODE_KIND)
#undef MVPL_DECLARE_NODE_KIND
}  // namespace nodes

namespace {
#define MVPL_NODE_KIND_ADDRESS(Name) &nodes::k##Name##Node,
const NodeKind* const kNodeKinds[] = {MVPL_NODE_KINDS(MVPL_NODE_KIND_ADDRESS)};
#undef MVPL_NODE_KIND_ADDRESS
}  // namespace

std::span<const NodeKind* const> node_kinds() {
    return kNodeKinds;
}

const NodeKind* find_node_kind(std::string_view name) {
    for (const NodeKind* kind : kNodeKinds) {
        if (kind->name == name) return kind;
    }
    return nullptr;
}

std::string glsl_function_call(GlslCallContext& c, std::string_view name,
                               std::initializer_list<std::string> args) {
    c.require(name);
    std::string call = std::string(name) + "(";
    for (const std::string& a : args)
        call += (call.back() == '(' ? "" : ", ") + a;
    return call + ")";
}

const NodeKind& node_kind(std::string_view name) {
    if (const NodeKind* kind = find_node_kind(name)) return *kind;
    throw std::logic_error("material: no node kind '" + std::string(name) + "'");
}

}  // namespace mvpl::material
