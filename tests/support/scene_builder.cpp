#include "tests/support/scene_builder.h"

#include <map>
#include <utility>

namespace mvpl::test {

scene::Material diffuse_material(const Rgb& albedo) {
    scene::Material m;
    m.base_color = albedo;
    m.metallic = 0.0f;
    m.roughness = 1.0f;
    m.specular = 0.0f;
    return m;
}

scene::Mesh make_quad(const Vec3& p, const Vec3& a, const Vec3& b, int material) {
    scene::Mesh mesh;
    mesh.positions = {p, p + a, p + a + b, p + b};
    const Vec3 n = glm::normalize(glm::cross(a, b));
    mesh.normals.assign(4, n);
    mesh.uv0 = {Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)};
    mesh.indices = {0, 1, 2, 0, 2, 3};
    mesh.material = material;
    return mesh;
}

scene::Mesh make_icosphere(const Vec3& center, float radius, int subdivisions, bool inward,
                           int material) {
    const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
    std::vector<Vec3> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                           {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                           {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    for (Vec3& p : v)
        p = glm::normalize(p);
    std::vector<uint32_t> f = {0, 11, 5,  0, 5,  1, 0, 1, 7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11,
                               4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3,  9,  4, 3,  4,  2, 3, 2, 6, 3,
                               6, 8,  3,  8, 9,  4, 9, 5, 2, 4, 11, 6,  2, 10, 8,  6, 7, 9, 8, 1};
    for (int s = 0; s < subdivisions; ++s) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> mid;
        auto midpoint = [&](uint32_t a, uint32_t b) {
            const auto key = std::minmax(a, b);
            auto it = mid.find(key);
            if (it != mid.end()) return it->second;
            v.push_back(glm::normalize(v[a] + v[b]));
            return mid[key] = uint32_t(v.size() - 1);
        };
        std::vector<uint32_t> g;
        for (size_t i = 0; i < f.size(); i += 3) {
            const uint32_t a = f[i], b = f[i + 1], c = f[i + 2];
            const uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
            g.insert(g.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
        }
        f = std::move(g);
    }
    scene::Mesh mesh;
    mesh.material = material;
    for (const Vec3& d : v) {
        mesh.positions.push_back(center + radius * d);
        mesh.normals.push_back(inward ? -d : d);
    }
    // The base icosahedron winds outwards; swap two corners to face inwards.
    if (inward) {
        for (size_t i = 0; i < f.size(); i += 3)
            std::swap(f[i + 1], f[i + 2]);
    }
    mesh.indices = std::move(f);
    return mesh;
}

scene::Scene make_integrating_sphere(float albedo, float radius, float intensity) {
    scene::Scene s;
    s.materials.push_back(diffuse_material(Rgb(albedo)));
    s.meshes.push_back(make_icosphere(Vec3(0.0f), radius, 5, true, 0));
    scene::Light light;
    light.type = scene::LightType::Point;
    light.intensity = Rgb(intensity);
    s.lights.push_back(light);
    s.camera = look_at(Vec3(0.0f, 0.0f, 0.5f * radius), Vec3(0.0f, 0.0f, -radius), 1.0f);
    s.has_camera = true;
    return s;
}

scene::Scene floor_under_sun(std::vector<scene::Mesh> objects) {
    scene::Scene s;
    s.materials = {diffuse_material(Rgb(0.7f))};
    s.meshes = {make_quad(Vec3(-3, 0, -3), Vec3(0, 0, 6), Vec3(6, 0, 0), 0)};
    for (scene::Mesh& m : objects)
        s.meshes.push_back(std::move(m));
    scene::Light sun;
    sun.type = scene::LightType::Directional;
    sun.intensity = Rgb(2.0f);
    sun.direction = glm::normalize(Vec3(0.5f, -1.0f, 0.3f));
    s.lights = {sun};
    s.camera = look_at(Vec3(0.0f, 4.0f, 4.0f), Vec3(0.0f), 0.9f);
    return s;
}

scene::Camera look_at(const Vec3& eye, const Vec3& target, float yfov) {
    const Vec3 back = glm::normalize(eye - target);
    Vec3 up(0, 1, 0);
    if (std::abs(glm::dot(up, back)) > 0.999f) up = Vec3(0, 0, 1);
    const Vec3 right = glm::normalize(glm::cross(up, back));
    const Vec3 true_up = glm::cross(back, right);
    scene::Camera camera;
    camera.camera_to_world = Mat4(Vec4(right, 0), Vec4(true_up, 0), Vec4(back, 0), Vec4(eye, 1));
    camera.yfov = yfov;
    return camera;
}

void scale_scene(scene::Scene& scene, float s) {
    for (scene::Mesh& mesh : scene.meshes) {
        for (Vec3& p : mesh.positions)
            p *= s;
    }
    for (scene::Light& light : scene.lights) {
        light.position *= s;
        if (light.type != scene::LightType::Directional) light.intensity *= s * s;
    }
    scene.camera.camera_to_world[3] = Vec4(Vec3(scene.camera.camera_to_world[3]) * s, 1.0f);
    scene.camera.znear *= s;
}

}  // namespace mvpl::test
