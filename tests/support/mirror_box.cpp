#include "tests/support/mirror_box.h"

#include "tests/support/scene_builder.h"

namespace mvpl::test {

scene::Scene make_mirror_box() {
    scene::Scene s;
    scene::Material gold;
    gold.base_color = Rgb(1.0f, 0.78f, 0.34f);
    gold.metallic = 1.0f;
    gold.roughness = 0.0f;
    s.materials = {diffuse_material(Rgb(0.75f)), diffuse_material(Rgb(0.7f, 0.1f, 0.1f)),
                   diffuse_material(Rgb(0.1f, 0.6f, 0.15f)), gold, diffuse_material(Rgb(0.0f))};
    s.materials[4].emissive = Rgb(8.0f);
    // Walls facing in (make_quad's front face is along cross(a, b)).
    s.meshes.push_back(make_quad(Vec3(-1, -1, -1), Vec3(0, 0, 2), Vec3(2, 0, 0), 0));  // floor
    s.meshes.push_back(make_quad(Vec3(-1, 1, -1), Vec3(2, 0, 0), Vec3(0, 0, 2), 0));   // ceiling
    s.meshes.push_back(make_quad(Vec3(-1, -1, -1), Vec3(2, 0, 0), Vec3(0, 2, 0), 0));  // back
    s.meshes.push_back(make_quad(Vec3(-1, -1, -1), Vec3(0, 2, 0), Vec3(0, 0, 2), 1));  // left
    s.meshes.push_back(make_quad(Vec3(1, -1, -1), Vec3(0, 0, 2), Vec3(0, 2, 0), 2));   // right
    s.meshes.push_back(
        make_quad(Vec3(-0.3f, 0.99f, -0.3f), Vec3(0.6f, 0, 0), Vec3(0, 0, 0.6f), 4));  // light
    s.meshes.push_back(make_icosphere(Vec3(0.0f), kMirrorSphereRadius, 4, false, 3));
    s.camera = look_at(Vec3(0.0f, 0.0f, 3.0f), Vec3(0.0f), 0.3f);
    s.has_camera = true;
    return s;
}

}  // namespace mvpl::test
