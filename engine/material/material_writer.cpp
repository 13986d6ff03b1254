#include "engine/material/material_writer.h"

namespace mvpl::material {
namespace {

// One node as its kind's glsl_call sees it.
class WriterNodeContext final : public GlslCallContext {
public:
    WriterNodeContext(MaterialWriter& writer, const Node& node) : m_writer(writer), m_node(node) {}

    const Node& node() const override { return m_node; }
    std::string input(int k) override { return m_writer.input(slot(k)); }
    std::string scalar(int k) override { return m_writer.scalar(slot(k)); }
    std::string rgb(int k) override { return m_writer.rgb(slot(k)); }
    std::string scalar_function(int k) override { return m_writer.scalar_function(slot(k)); }
    Vec2 texel_step(int k) const override { return m_writer.texel_step(slot(k)); }
    const scene::Texture* texture() const override { return m_writer.texture(m_node.texture); }
    std::string sampler() override { return m_writer.sampler(m_node.texture); }
    void require(std::string_view function) override { m_writer.require(function); }

private:
    const NodeInput& slot(int k) const { return m_node.inputs[size_t(k)]; }

    MaterialWriter& m_writer;
    const Node& m_node;
};

}  // namespace

std::string MaterialWriter::node(int index) {
    const Node& n = m_graph->nodes.at(size_t(index));
    WriterNodeContext context(*this, n);
    return n.kind->glsl_call(context);
}

}  // namespace mvpl::material
