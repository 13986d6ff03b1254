#include "engine/material/node_graph.h"

#include <algorithm>
#include <stdexcept>

namespace mvpl::material {

int MaterialGraph::add(const Node& node) {
    if (!node.kind) throw std::logic_error("material graph: a node without a kind");
    nodes.push_back(node);
    return int(nodes.size()) - 1;
}

std::vector<const NodeKind*> MaterialGraph::kinds() const {
    std::vector<bool> seen_node(nodes.size(), false);
    std::vector<const NodeKind*> seen;
    std::vector<int> stack;
    for (const int root : {closure, emission, normal}) {
        if (root >= 0) stack.push_back(root);
    }
    while (!stack.empty()) {
        const int i = stack.back();
        stack.pop_back();
        if (i < 0 || size_t(i) >= nodes.size() || seen_node[size_t(i)]) continue;
        seen_node[size_t(i)] = true;
        const Node& n = nodes[size_t(i)];
        if (std::find(seen.begin(), seen.end(), n.kind) == seen.end()) seen.push_back(n.kind);
        for (const NodeInput& in : n.inputs) {
            if (in.node >= 0) stack.push_back(in.node);
        }
    }
    std::vector<const NodeKind*> ordered;
    for (const NodeKind* kind : node_kinds()) {
        if (std::find(seen.begin(), seen.end(), kind) != seen.end()) ordered.push_back(kind);
    }
    return ordered;
}

}  // namespace mvpl::material
