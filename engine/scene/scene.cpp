#include "engine/scene/scene.h"

namespace mvpl::scene {

Bounds Scene::bounds() const {
    Bounds b;
    for (const Mesh& mesh : meshes) {
        for (const Vec3& p : mesh.positions)
            b.extend(p);
    }
    return b;
}

std::vector<bool> Scene::drawn_materials() const {
    std::vector<bool> drawn(materials.size(), false);
    for (const Mesh& m : meshes) {
        if (m.triangle_count() == 0 || drawn.empty()) continue;
        drawn[m.material >= 0 && size_t(m.material) < drawn.size() ? size_t(m.material) : 0] = true;
    }
    return drawn;
}

size_t Scene::triangle_count() const {
    size_t n = 0;
    for (const Mesh& mesh : meshes)
        n += mesh.triangle_count();
    return n;
}

}  // namespace mvpl::scene
