#include "engine/material/graph_eval.h"

namespace mvpl::material {
namespace {

const Node& node_at(const MaterialGraph& graph, int i) {
    return graph.nodes.at(size_t(i));
}

Vec4 evaluate_node(const MaterialGraph& graph, int index,
                   const std::vector<scene::Texture>& textures, const SurfacePoint& p) {
    const Node& n = node_at(graph, index);
    const auto in = [&](int k) { return evaluate_input(graph, n.inputs[size_t(k)], textures, p); };
    switch (n.kind) {
        case NodeKind::Constant:
            return n.value;
        case NodeKind::ImageTexture: {
            if (!n.texture.valid() || size_t(n.texture.texture) >= textures.size()) return n.value;
            const Vec2& uv = n.texture.texcoord == 1 ? p.uv1 : p.uv0;
            return image_texture(textures[size_t(n.texture.texture)], n.texture, n.value, uv);
        }
        case NodeKind::VertexColor:
            return vertex_color(n.value, p.color);
        case NodeKind::Mix:
            return mix_node(in(0), in(1), in(2).x);
        case NodeKind::Emission:
            return emission(in(0), n.value.x);
        default:
            // Normal and closure nodes have no vec4 value.
            return Vec4(0.0f);
    }
}

}  // namespace

Vec4 evaluate_input(const MaterialGraph& graph, const NodeInput& input,
                    const std::vector<scene::Texture>& textures, const SurfacePoint& p) {
    if (input.node < 0) return Vec4(0.0f);
    const Vec4 v = evaluate_node(graph, input.node, textures, p);
    return input.channel == kAllChannels ? v : Vec4(v[input.channel]);
}

ClosureParams evaluate_closure(const MaterialGraph& graph,
                               const std::vector<scene::Texture>& textures, const SurfacePoint& p) {
    if (graph.closure < 0) return lambertian(Rgb(0.0f));
    const Node& n = node_at(graph, graph.closure);
    const auto in = [&](int k) { return evaluate_input(graph, n.inputs[size_t(k)], textures, p); };
    const auto rgb = [&](int k) { return Rgb(Vec3(in(k))); };
    const auto scalar = [&](int k) { return in(k).x; };
    switch (n.kind) {
        case NodeKind::Lambertian:
            return lambertian(rgb(0));
        case NodeKind::GgxConductor:
            return ggx_conductor(rgb(0), scalar(1));
        case NodeKind::DielectricDiffuse:
            return dielectric_diffuse(rgb(0), scalar(1), scalar(2), rgb(3), scalar(4));
        case NodeKind::MetalRough:
            return metal_rough(rgb(0), scalar(1), scalar(2), scalar(3), rgb(4), scalar(5));
        case NodeKind::RoughDielectric:
            return rough_dielectric(scalar(0), scalar(1), rgb(2), scalar(3));
        default:
            return lambertian(Rgb(0.0f));
    }
}

Rgb evaluate_emission(const MaterialGraph& graph, const std::vector<scene::Texture>& textures,
                      const SurfacePoint& p) {
    if (graph.emission < 0) return Rgb(0.0f);
    return Rgb(Vec3(evaluate_node(graph, graph.emission, textures, p)));
}

Vec2 bump_step(const MaterialGraph& graph, const NodeInput& height,
               const std::vector<scene::Texture>& textures) {
    std::vector<int> stack{height.node};
    while (!stack.empty()) {
        const int i = stack.back();
        stack.pop_back();
        if (i < 0) continue;
        const Node& n = node_at(graph, i);
        if (n.kind == NodeKind::ImageTexture && n.texture.valid() &&
            size_t(n.texture.texture) < textures.size()) {
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

Vec3 evaluate_normal(const MaterialGraph& graph, const std::vector<scene::Texture>& textures,
                     const SurfacePoint& p) {
    if (graph.normal < 0) return p.frame.n;
    const Node& n = node_at(graph, graph.normal);
    if (n.kind == NodeKind::NormalMap) {
        return normal_map(Vec3(evaluate_input(graph, n.inputs[0], textures, p)), n.value.x,
                          p.frame);
    }
    if (n.kind == NodeKind::BumpMap) {
        const Vec2 step = bump_step(graph, n.inputs[0], textures);
        // The height at (u, v), (u + du, v) and (u, v + dv), both uv sets shifted alike.
        SurfacePoint pu = p;
        pu.uv0.x += step.x;
        pu.uv1.x += step.x;
        SurfacePoint pv = p;
        pv.uv0.y += step.y;
        pv.uv1.y += step.y;
        const float h = evaluate_input(graph, n.inputs[0], textures, p).x;
        const float h_u = evaluate_input(graph, n.inputs[0], textures, pu).x;
        const float h_v = evaluate_input(graph, n.inputs[0], textures, pv).x;
        return bump_map(h, h_u, h_v, step.x, step.y, n.value.x, p.frame);
    }
    return p.frame.n;
}

}  // namespace mvpl::material
