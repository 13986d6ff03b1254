#include "engine/material/graph_eval.h"

namespace mvpl::material {
namespace {

const Node& node_at(const MaterialGraph& graph, int i) {
    return graph.nodes.at(size_t(i));
}

// One node's evaluation: its inputs are evaluated on demand, at the point or at a moved one.
class GraphNodeContext final : public NodeContext {
public:
    GraphNodeContext(const MaterialGraph& graph, int index,
                     const std::vector<scene::Texture>& textures, const SurfacePoint& p)
        : m_graph(graph), m_node(node_at(graph, index)), m_textures(textures), m_point(p) {}

    const Node& node() const override { return m_node; }
    const SurfacePoint& point() const override { return m_point; }
    Vec4 input_at(int k, const SurfacePoint& p) const override {
        return evaluate_input(m_graph, m_node.inputs[size_t(k)], m_textures, p);
    }
    Vec2 texel_step(int k) const override {
        return bump_step(m_graph, m_node.inputs[size_t(k)], m_textures);
    }
    const scene::Texture* texture() const override {
        const scene::TextureRef& ref = m_node.texture;
        if (!ref.valid() || size_t(ref.texture) >= m_textures.size()) return nullptr;
        return &m_textures[size_t(ref.texture)];
    }

private:
    const MaterialGraph& m_graph;
    const Node& m_node;
    const std::vector<scene::Texture>& m_textures;
    const SurfacePoint& m_point;
};

ClosureParams black() {
    return make_closure(Rgb(0.0f), 0.0f, 1.0f, 0.0f, Rgb(1.0f), 1.5f);
}

}  // namespace

Vec4 evaluate_input(const MaterialGraph& graph, const NodeInput& input,
                    const std::vector<scene::Texture>& textures, const SurfacePoint& p) {
    if (input.node < 0) return Vec4(0.0f);
    const Node& n = node_at(graph, input.node);
    if (!n.kind->value) return Vec4(0.0f);  // normal and closure nodes have no vec4 value
    const Vec4 v = n.kind->value(GraphNodeContext(graph, input.node, textures, p));
    return input.channel == kAllChannels ? v : Vec4(v[input.channel]);
}

ClosureParams evaluate_closure(const MaterialGraph& graph,
                               const std::vector<scene::Texture>& textures, const SurfacePoint& p) {
    if (graph.closure < 0) return black();
    const Node& n = node_at(graph, graph.closure);
    if (!n.kind->closure) return black();
    ClosureParams c = n.kind->closure(GraphNodeContext(graph, graph.closure, textures, p));
    if (graph.transmission.node >= 0) {
        c.transmission = Rgb(Vec3(evaluate_input(graph, graph.transmission, textures, p)));
        c.thin_walled = graph.thin_walled;
        c = clamp_to_valid_ranges(c);
    }
    return c;
}

Rgb evaluate_emission(const MaterialGraph& graph, const std::vector<scene::Texture>& textures,
                      const SurfacePoint& p) {
    if (graph.emission < 0) return Rgb(0.0f);
    return Rgb(Vec3(evaluate_input(graph, {graph.emission, kAllChannels}, textures, p)));
}

Vec3 evaluate_normal(const MaterialGraph& graph, const std::vector<scene::Texture>& textures,
                     const SurfacePoint& p) {
    if (graph.normal < 0) return p.frame.n;
    const Node& n = node_at(graph, graph.normal);
    if (!n.kind->normal) return p.frame.n;
    return n.kind->normal(GraphNodeContext(graph, graph.normal, textures, p));
}

Vec2 bump_step(const MaterialGraph& graph, const NodeInput& height,
               const std::vector<scene::Texture>& textures) {
    std::vector<int> stack{height.node};
    while (!stack.empty()) {
        const int i = stack.back();
        stack.pop_back();
        if (i < 0) continue;
        const Node& n = node_at(graph, i);
        // A node with a texture reference reads that texture (image_texture today).
        if (n.texture.valid() && size_t(n.texture.texture) < textures.size()) {
            const scene::Texture& t = textures[size_t(n.texture.texture)];
            if (t.width > 0 && t.height > 0)
                return Vec2(1.0f / float(t.width), 1.0f / float(t.height));
        }
        for (const NodeInput& in : n.inputs) {
            if (in.node >= 0) stack.push_back(in.node);
        }
    }
    return Vec2(1.0f / 1024.0f);
}

}  // namespace mvpl::material
