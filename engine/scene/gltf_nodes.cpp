#include "engine/scene/gltf_nodes.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <string>
#include <utility>
#include <vector>

#include "engine/scene/gltf_value.h"
#include "engine/scene/scene_range.h"

namespace mvpl::scene::gltf {
namespace {

std::string node_name(int node) {
    return "node " + std::to_string(node);
}

bool all_finite(const std::vector<double>& values) {
    for (double v : values) {
        if (!std::isfinite(v)) return false;
    }
    return true;
}

bool all_finite(const DMat4& m) {
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            if (!std::isfinite(m[c][r])) return false;
        }
    }
    return true;
}

// A node's matrix, translation, rotation or scale: the right number of finite numbers, each
// within `limit` (translations place things in the world: scene_range.h's kMaxCoordinate bounds
// them and, as generously, the matrix and scale).
const std::vector<double>& checked(const Document& doc, int node, const std::vector<double>& values,
                                   size_t size, const char* what, double limit) {
    if (!values.empty() && values.size() != size) {
        doc.fail(node_name(node) + " has a " + what + " of " + std::to_string(values.size()) +
                 " numbers, not " + std::to_string(size));
    }
    if (!all_finite(values)) doc.fail(node_name(node) + " has a non-finite " + what);
    for (size_t i = 0; i < values.size(); ++i) {
        check_magnitude(doc, values[i], limit,
                        indexed(indexed("nodes", size_t(node)) + "." + what, i));
    }
    return values;
}

DMat4 local_transform(const Document& doc, int index) {
    const tinygltf::Node& node = doc.model.nodes[size_t(index)];
    if (!node.matrix.empty()) {
        return glm::make_mat4(
            checked(doc, index, node.matrix, 16, "matrix", kMaxCoordinate).data());  // column-major
    }
    DMat4 m(1.0);
    const std::vector<double>& t =
        checked(doc, index, node.translation, 3, "translation", kMaxCoordinate);
    // A unit quaternion is expected; kMaxFactor only keeps its length from overflowing.
    const std::vector<double>& r = checked(doc, index, node.rotation, 4, "rotation", kMaxFactor);
    const std::vector<double>& s = checked(doc, index, node.scale, 3, "scale", kMaxCoordinate);
    if (!t.empty()) m = glm::translate(m, DVec3(t[0], t[1], t[2]));
    if (!r.empty()) {
        const glm::dquat q(r[3], r[0], r[1], r[2]);  // glTF stores x, y, z, w
        const double length = glm::length(q);
        if (!(length > 0.0) || !std::isfinite(length)) {
            doc.fail(node_name(index) + " has a zero rotation quaternion");
        }
        m = m * glm::mat4_cast(q / length);
    }
    if (!s.empty()) m = glm::scale(m, DVec3(s[0], s[1], s[2]));
    return m;
}

// Colours for the depth-first cycle search.
enum class Mark : unsigned char { Unseen, OnPath, Done };

void check_cycles(const Document& doc) {
    const auto& nodes = doc.model.nodes;
    std::vector<Mark> mark(nodes.size(), Mark::Unseen);
    std::vector<std::pair<int, size_t>> stack;  // node, next child; no recursion on deep chains
    for (size_t start = 0; start < nodes.size(); ++start) {
        if (mark[start] != Mark::Unseen) continue;
        mark[start] = Mark::OnPath;
        stack.emplace_back(int(start), 0);
        while (!stack.empty()) {
            auto& [node, next] = stack.back();
            const std::vector<int>& children = nodes[size_t(node)].children;
            if (next == children.size()) {
                mark[size_t(node)] = Mark::Done;
                stack.pop_back();
                continue;
            }
            const int child = children[next++];
            if (mark[size_t(child)] == Mark::OnPath)
                doc.fail("node cycle through node " + std::to_string(child));
            if (mark[size_t(child)] == Mark::Unseen) {
                mark[size_t(child)] = Mark::OnPath;
                stack.emplace_back(child, 0);
            }
        }
    }
}

// Parent of every node (-1 for none), after checking child indices, cycles and shared children.
std::vector<int> parents_of(const Document& doc) {
    const auto& nodes = doc.model.nodes;
    for (size_t n = 0; n < nodes.size(); ++n) {
        for (int child : nodes[n].children) {
            if (child < 0 || size_t(child) >= nodes.size()) {
                doc.fail(node_name(int(n)) + " has child " + std::to_string(child) +
                         ", but the file has " + std::to_string(nodes.size()) + " nodes");
            }
        }
    }
    check_cycles(doc);
    std::vector<int> parent(nodes.size(), -1);
    for (size_t n = 0; n < nodes.size(); ++n) {
        for (int child : nodes[n].children) {
            const int previous = parent[size_t(child)];
            if (previous == int(n)) {
                doc.fail(node_name(int(n)) + " lists child " + std::to_string(child) + " twice");
            }
            if (previous >= 0) {
                doc.fail(node_name(child) + " has two parents: nodes " + std::to_string(previous) +
                         " and " + std::to_string(n));
            }
            parent[size_t(child)] = int(n);
        }
    }
    return parent;
}

std::vector<int> scene_roots(const Document& doc, const std::vector<int>& parent) {
    const tinygltf::Model& model = doc.model;
    if (model.scenes.empty()) {
        std::vector<int> roots;
        for (size_t n = 0; n < parent.size(); ++n) {
            if (parent[n] < 0) roots.push_back(int(n));
        }
        return roots;
    }
    int scene = 0;
    if (model.defaultScene != -1) {
        scene = model.defaultScene;
        if (scene < 0 || size_t(scene) >= model.scenes.size()) {
            doc.fail("the default scene " + std::to_string(scene) +
                     " does not exist (the file has " + std::to_string(model.scenes.size()) +
                     " scenes)");
        }
    }
    const std::string scene_name = "scene " + std::to_string(scene);
    const std::vector<int>& roots = model.scenes[size_t(scene)].nodes;
    std::vector<bool> listed(parent.size(), false);
    for (int root : roots) {
        if (root < 0 || size_t(root) >= parent.size()) {
            doc.fail(scene_name + " refers to node " + std::to_string(root) +
                     ", but the file has " + std::to_string(parent.size()) + " nodes");
        }
        if (listed[size_t(root)])
            doc.fail(scene_name + " lists node " + std::to_string(root) + " twice");
        listed[size_t(root)] = true;
        if (parent[size_t(root)] >= 0) {
            doc.fail(node_name(root) + " is a root of " + scene_name +
                     " but also a child of node " + std::to_string(parent[size_t(root)]));
        }
    }
    return roots;
}

}  // namespace

void walk_scene(const Document& doc, const std::function<void(int, const DMat4&)>& visit) {
    const std::vector<int> parent = parents_of(doc);
    const std::vector<int> roots = scene_roots(doc, parent);
    // Explicit stack: a chain of a million nodes must not exhaust the call stack.
    std::vector<std::pair<int, DMat4>> stack;
    for (auto root = roots.rbegin(); root != roots.rend(); ++root)
        stack.emplace_back(*root, DMat4(1.0));
    while (!stack.empty()) {
        const auto [node, parent_world] = stack.back();
        stack.pop_back();
        const DMat4 world = parent_world * local_transform(doc, node);
        if (!all_finite(world)) {
            doc.fail(node_name(node) +
                     " has a non-finite world transform (its own or its parents' "
                     "transforms overflow)");
        }
        visit(node, world);
        const std::vector<int>& children = doc.model.nodes[size_t(node)].children;
        for (auto child = children.rbegin(); child != children.rend(); ++child) {
            stack.emplace_back(*child, world);
        }
    }
}

}  // namespace mvpl::scene::gltf
