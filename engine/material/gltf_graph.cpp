// graph_from_gltf (node_graph.h): a glTF metallic-roughness material as a node graph.
#include "engine/material/node_graph.h"

namespace mvpl::material {

namespace {

Node constant(const Vec4& v) {
    Node n;
    n.kind = &node_kind("constant");
    n.value = v;
    return n;
}

Node texture(const scene::TextureRef& ref, const Vec4& factor) {
    Node n;
    n.kind = &node_kind("image_texture");
    n.texture = ref;
    n.value = factor;
    return n;
}

// One material parameter: the texture channel times the factor, or the factor alone.
class Builder {
public:
    explicit Builder(MaterialGraph& graph) : m_graph(graph) {}

    NodeInput value(const scene::TextureRef& ref, const Vec4& factor, int channel) {
        if (ref.valid()) return {m_graph.add(texture(ref, factor)), channel};
        return {m_graph.add(constant(factor)), channel};
    }
    NodeInput scalar(float v) { return {m_graph.add(constant(Vec4(v))), 0}; }
    bool is_constant(const NodeInput& in, float v) const {
        const Node& n = m_graph.nodes[size_t(in.node)];
        return n.kind == &node_kind("constant") && n.value[in.channel < 0 ? 0 : in.channel] == v;
    }

private:
    MaterialGraph& m_graph;
};

}  // namespace

namespace {

// The metallic-roughness closure node (with KHR_materials_specular, _ior and _transmission) for
// the base colour `base`; sets the graph's transmission output.
Node metal_rough_closure(MaterialGraph& g, const scene::Material& m, NodeInput base) {
    Builder b(g);
    // metallicRoughnessTexture: roughness in G, metallic in B; one texture node serves both.
    NodeInput metallic;
    NodeInput roughness;
    if (m.metallic_roughness_texture.valid()) {
        const int t =
            g.add(texture(m.metallic_roughness_texture, Vec4(1.0f, m.roughness, m.metallic, 1.0f)));
        metallic = {t, 2};
        roughness = {t, 1};
    } else {
        metallic = b.scalar(m.metallic);
        roughness = b.scalar(m.roughness);
    }
    // KHR_materials_specular: strength in the texture's A channel.
    const NodeInput specular =
        m.specular_texture.valid()
            ? b.value(m.specular_texture, Vec4(1.0f, 1.0f, 1.0f, m.specular), 3)
            : b.scalar(m.specular);
    const NodeInput specular_color =
        b.value(m.specular_color_texture, Vec4(m.specular_color, 1.0f), kAllChannels);
    const NodeInput ior = b.scalar(m.ior);

    // KHR_materials_transmission: the closure node's base is scaled by (1 − t) (the reflection,
    // which the GPU shades too), the graph's transmission output is t · base (the BTDF's tint).
    const NodeInput transmission = b.value(m.transmission_texture, Vec4(m.transmission), 0);
    const bool opaque = b.is_constant(transmission, 0.0f);
    const bool clear = b.is_constant(transmission, 1.0f);
    if (!opaque) {
        Node tint;
        tint.kind = &node_kind("multiply");
        tint.inputs[0] = base;
        tint.inputs[1] = transmission;
        g.transmission = {g.add(tint), kAllChannels};
        g.thin_walled = !(m.thickness > 0.0f);
    }
    if (!opaque && !clear) {
        Node mix;
        mix.kind = &node_kind("mix_node");
        mix.inputs[0] = base;
        mix.inputs[1] = {g.add(constant(Vec4(0.0f, 0.0f, 0.0f, 1.0f))), kAllChannels};
        mix.inputs[2] = transmission;
        base = {g.add(mix), kAllChannels};
    }

    Node closure;
    const bool metal_const = g.nodes[size_t(metallic.node)].kind == &node_kind("constant");
    if (metal_const && m.metallic <= 0.0f && clear) {
        closure.kind = &node_kind("rough_dielectric");
        closure.inputs = {roughness, specular, specular_color, ior, NodeInput{}, NodeInput{}};
    } else if (metal_const && m.metallic <= 0.0f && b.is_constant(specular, 0.0f)) {
        closure.kind = &node_kind("lambertian");
        closure.inputs[0] = base;
    } else if (metal_const && m.metallic >= 1.0f) {
        closure.kind = &node_kind("ggx_conductor");
        closure.inputs[0] = base;
        closure.inputs[1] = roughness;
    } else if (metal_const && m.metallic <= 0.0f) {
        closure.kind = &node_kind("dielectric_diffuse");
        closure.inputs = {base, roughness, specular, specular_color, ior, NodeInput{}};
    } else {
        closure.kind = &node_kind("metal_rough");
        closure.inputs = {base, metallic, roughness, specular, specular_color, ior};
    }
    return closure;
}

// KHR_materials_pbrSpecularGlossiness: specular in the texture's RGB, glossiness in its A; one
// texture node serves both.
Node spec_gloss_closure(MaterialGraph& g, const scene::Material& m, NodeInput diffuse) {
    Builder b(g);
    const NodeInput specular = b.value(m.specular_glossiness_texture,
                                       Vec4(m.spec_gloss_specular, m.glossiness), kAllChannels);
    Node closure;
    closure.kind = &node_kind("spec_gloss");
    closure.inputs[0] = diffuse;
    closure.inputs[1] = specular;
    closure.inputs[2] = {specular.node, 3};
    return closure;
}

// KHR_materials_unlit: a surface that reflects nothing (a black Lambertian) and emits its base
// colour (node_graph.h says why an emitter).
Node unlit_closure(MaterialGraph& g, const scene::Material& m, NodeInput base) {
    if (m.is_emissive()) {
        Node e;
        e.kind = &node_kind("emission");
        e.value = Vec4(1.0f);
        e.inputs[0] = base;
        g.emission = g.add(e);
    }
    Node closure;
    closure.kind = &node_kind("lambertian");
    closure.inputs[0] = {g.add(constant(Vec4(0.0f, 0.0f, 0.0f, 1.0f))), kAllChannels};
    return closure;
}

}  // namespace

MaterialGraph graph_from_gltf(const scene::Material& m, const GltfGraphOptions& options) {
    MaterialGraph g;
    g.double_sided = m.double_sided;
    Builder b(g);
    NodeInput base = b.value(m.base_color_texture, Vec4(m.base_color, m.base_alpha), kAllChannels);
    if (options.vertex_colors) {
        Node colour;
        colour.kind = &node_kind("vertex_color");
        Node product;
        product.kind = &node_kind("multiply");
        product.inputs[0] = base;
        product.inputs[1] = {g.add(colour), kAllChannels};
        base = {g.add(product), kAllChannels};
    }
    g.alpha_mode = m.alpha_mode;
    g.alpha_cutoff = m.alpha_cutoff;
    // Before the transmission mix, which overwrites the alpha channel.
    if (m.alpha_mode != scene::AlphaMode::Opaque) {
        g.alpha = m.opacity_texture.valid() ? b.value(m.opacity_texture, Vec4(m.base_alpha), 3)
                                            : NodeInput{base.node, 3};
    }
    switch (m.shading) {
        case scene::ShadingModel::Unlit:
            // The spec ignores every other property "related to lighting or colour".
            g.closure = g.add(unlit_closure(g, m, base));
            return g;
        case scene::ShadingModel::SpecGloss:
            g.closure = g.add(spec_gloss_closure(g, m, base));
            break;
        case scene::ShadingModel::MetalRough:
            g.closure = g.add(metal_rough_closure(g, m, base));
            break;
    }

    if (m.is_emissive() || (m.emissive_texture.valid() && max_component(m.emission()) > 0.0f)) {
        Node e;
        e.kind = &node_kind("emission");
        e.value = Vec4(m.emissive_strength);
        e.inputs[0] = b.value(m.emissive_texture, Vec4(m.emissive, 1.0f), kAllChannels);
        g.emission = g.add(e);
    }
    if (m.normal_texture.valid()) {
        Node n;
        n.kind = &node_kind("normal_map");
        n.value = Vec4(m.normal_scale);
        n.inputs[0] = b.value(m.normal_texture, Vec4(1.0f), kAllChannels);
        g.normal = g.add(n);
    } else if (m.bump_texture.valid()) {
        Node n;
        n.kind = &node_kind("bump_map");
        n.value = Vec4(m.bump_scale);
        n.inputs[0] = b.value(m.bump_texture, Vec4(1.0f), 0);
        g.normal = g.add(n);
    }
    return g;
}

}  // namespace mvpl::material
