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

size_t Scene::triangle_count() const {
    size_t n = 0;
    for (const Mesh& mesh : meshes)
        n += mesh.triangle_count();
    return n;
}

}  // namespace mvpl::scene
