#include "tests/integrator/caustic_scenes.h"

#include "tests/support/scene_builder.h"

namespace mvpl::integrator {

scene::Scene make_pane_scene(bool glass) {
    scene::Scene s;
    scene::Material pane = test::diffuse_material(Rgb(0.5f));
    if (glass) {
        pane.base_color = Rgb(1.0f);
        pane.roughness = 0.0f;
        pane.ior = 1.5f;
        pane.transmission = 1.0f;
        pane.double_sided = true;
    }
    s.materials = {test::diffuse_material(Rgb(0.8f)), test::diffuse_material(Rgb(0.0f)), pane,
                   test::diffuse_material(Rgb(0.7f))};
    s.materials[1].emissive = Rgb(4.0f);
    s.meshes.push_back(test::make_quad(Vec3(-2, 0, -1.5f), Vec3(0, 0, 3.5f), Vec3(4, 0, 0), 0));
    s.meshes.push_back(test::make_quad(Vec3(-2, 0, -1.5f), Vec3(4, 0, 0), Vec3(0, 2, 0), 3));
    const float l = kLightHalf, h = kPaneHalf;
    s.meshes.push_back(  // facing down
        test::make_quad(Vec3(-l, 1.0f, -l), Vec3(2 * l, 0, 0), Vec3(0, 0, 2 * l), 1));
    s.meshes.push_back(
        test::make_quad(Vec3(-h, kPaneY, -h), Vec3(2 * h, 0, 0), Vec3(0, 0, 2 * h), 2));
    scene::Light point;
    point.position = Vec3(1.2f, 0.3f, 0.0f);
    point.intensity = Rgb(1.0f);
    s.lights.push_back(point);
    s.camera = test::look_at(Vec3(0.0f, 0.45f, 1.4f), Vec3(0.0f, 0.0f, -0.1f), 1.0f);
    s.has_camera = true;
    return s;
}

scene::Scene make_mirror_scene() {
    scene::Scene s;
    scene::Material mirror;
    mirror.base_color = Rgb(0.9f);
    mirror.metallic = 1.0f;
    mirror.roughness = 0.05f;
    s.materials = {test::diffuse_material(Rgb(0.8f)), test::diffuse_material(Rgb(0.0f)), mirror};
    s.materials[1].emissive = Rgb(4.0f);
    s.meshes.push_back(test::make_quad(Vec3(-2, 0, -1.5f), Vec3(0, 0, 3.5f), Vec3(4, 0, 0), 0));
    s.meshes.push_back(  // facing down
        test::make_quad(Vec3(-0.05f, 1.0f, -0.25f), Vec3(0.5f, 0, 0), Vec3(0, 0, 0.5f), 1));
    s.meshes.push_back(  // facing −X
        test::make_quad(Vec3(0.8f, 0.0f, -0.6f), Vec3(0, 0, 1.2f), Vec3(0, 1.0f, 0), 2));
    s.camera = test::look_at(Vec3(-1.0f, 0.8f, 1.2f), Vec3(0.3f, 0.0f, -0.2f), 1.0f);
    s.has_camera = true;
    return s;
}

}  // namespace mvpl::integrator
