#include "tests/stability/stability_scenes.h"

#include "tests/support/scene_builder.h"

namespace mvpl::test {

scene::Scene make_point_light_room() {
    scene::Scene s;
    s.materials.push_back(diffuse_material(Rgb(0.7f)));
    s.materials.push_back(diffuse_material(Rgb(0.8f, 0.3f, 0.2f)));
    s.meshes.push_back(make_quad(Vec3(-2, 0, -2), Vec3(0, 0, 4), Vec3(4, 0, 0), 0));
    s.meshes.push_back(make_quad(Vec3(-2, 0, -1), Vec3(4, 0, 0), Vec3(0, 3, 0), 1));
    scene::Light light;
    light.type = scene::LightType::Point;
    light.position = Vec3(0.5f, 1.5f, 0.5f);
    light.intensity = Rgb(6.0f, 5.0f, 4.0f);
    s.lights.push_back(light);
    s.camera = look_at(Vec3(0.0f, 1.8f, 3.5f), Vec3(0.0f, 0.6f, -0.5f), 0.9f);
    s.has_camera = true;
    return s;
}

void scale_emission(scene::Scene& scene, float k) {
    for (scene::Light& light : scene.lights)
        light.intensity = light.intensity * k;
    for (scene::Material& m : scene.materials)
        m.emissive = m.emissive * k;
}

namespace {

// One triangle with the given vertices and one normal for all three (the loader's fallback for
// a zero-area face is a unit normal too: every vertex has a normal, scene.h).
scene::Mesh make_triangle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& n,
                          int material) {
    scene::Mesh m;
    m.positions = {a, b, c};
    m.normals = {n, n, n};
    m.indices = {0, 1, 2};
    m.material = material;
    return m;
}

}  // namespace

scene::Scene make_degenerate_scene() {
    scene::Scene s = make_point_light_room();
    const Vec3 up(0, 1, 0), toward(0, 0, 1);
    const float ulp = 1.2e-7f;  // float ulp at 1
    // Zero area on the floor: collinear, two coincident, three coincident vertices.
    s.meshes.push_back(
        make_triangle(Vec3(-1, 0.01f, 0), Vec3(0, 0.01f, 0.5f), Vec3(1, 0.01f, 1), up, 0));
    s.meshes.push_back(make_triangle(Vec3(0.2f, 0.02f, 0.2f), Vec3(0.2f, 0.02f, 0.2f),
                                     Vec3(0.8f, 0.02f, 0.4f), up, 0));
    s.meshes.push_back(make_triangle(Vec3(0.3f, 0.5f, 0.3f), Vec3(0.3f, 0.5f, 0.3f),
                                     Vec3(0.3f, 0.5f, 0.3f), up, 1));
    // Slivers: 1.5 m long, a few ulps wide, one flat on the floor and one standing in the light.
    s.meshes.push_back(make_triangle(Vec3(-1.0f, 0.03f, 0.6f), Vec3(0.5f, 0.03f, 0.6f),
                                     Vec3(0.5f, 0.03f, 0.6f + 4 * ulp), up, 1));
    s.meshes.push_back(make_triangle(Vec3(-0.5f, 0.2f, 0.0f), Vec3(1.0f, 0.2f, 0.0f),
                                     Vec3(1.0f, 0.2f + 3 * ulp, 0.0f), toward, 1));
    return s;
}

scene::Scene make_near_mirror_scene() {
    scene::Scene s;
    scene::Material mirror = diffuse_material(Rgb(0.9f));
    mirror.metallic = 1.0f;
    mirror.roughness = 1e-3f;
    s.materials.push_back(mirror);
    s.materials.push_back(diffuse_material(Rgb(0.6f, 0.6f, 0.3f)));
    s.meshes.push_back(make_quad(Vec3(-3, 0, -3), Vec3(0, 0, 6), Vec3(6, 0, 0), 0));
    s.meshes.push_back(make_quad(Vec3(-3, 0, -2), Vec3(6, 0, 0), Vec3(0, 3, 0), 1));
    scene::Light light;
    light.type = scene::LightType::Point;
    light.position = Vec3(0.0f, 0.4f, 1.5f);
    light.intensity = Rgb(4.0f);
    s.lights.push_back(light);
    // 2° above the floor plane at 4 m: most floor pixels are seen at 85–89° from the normal.
    const Vec3 eye(0.0f, 0.14f, 4.0f);
    s.camera = look_at(eye, Vec3(0.0f, 0.0f, 0.0f), 0.5f);
    s.has_camera = true;
    return s;
}

}  // namespace mvpl::test
