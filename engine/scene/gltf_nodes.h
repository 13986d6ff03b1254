#pragma once
// The node hierarchy: checked for cycles and shared children, walked in double precision.
#include <functional>

#include "engine/core/math.h"
#include "engine/scene/gltf_document.h"

namespace mvpl::scene::gltf {

// Calls visit(node, world transform) for every node of the scene to show (the default scene,
// else scene 0, else every parentless node), depth first, parents before children, in file
// order. Throws InputError for out-of-range node indices, cycles, nodes with two parents and
// non-finite transforms.
void walk_scene(const Document& doc, const std::function<void(int, const DMat4&)>& visit);

}  // namespace mvpl::scene::gltf
