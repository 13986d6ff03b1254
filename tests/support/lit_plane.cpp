#include "tests/support/lit_plane.h"

#include <algorithm>

#include "tests/support/scene_builder.h"

namespace mvpl::test {

scene::Scene make_lit_plane(const scene::Light& light) {
    scene::Scene s;
    s.materials.push_back(diffuse_material(Rgb(kLitPlaneAlbedo)));
    s.meshes.push_back(make_quad(Vec3(-2, 0, -2), Vec3(0, 0, 4), Vec3(4, 0, 0), 0));
    s.lights.push_back(light);
    s.camera = look_at(Vec3(0.3f, 3.0f, 0.2f), Vec3(0.3f, 0.0f, 0.0f), 0.9f);
    s.has_camera = true;
    return s;
}

Rgb lit_plane_radiance(const scene::Light& light, const Vec3& p) {
    const Vec3 n(0, 1, 0);
    const float rho_over_pi = kLitPlaneAlbedo * kInvPi;
    if (light.type == scene::LightType::Directional) {
        return rho_over_pi * light.intensity * std::max(0.0f, glm::dot(n, -light.direction));
    }
    const Vec3 d = light.position - p;
    const float dist2 = glm::dot(d, d);
    const Vec3 wi = d / std::sqrt(dist2);
    float falloff = 1.0f;
    if (light.type == scene::LightType::Spot) {
        // KHR_lights_punctual's reference falloff, written out independently of the renderer.
        const float scale =
            1.0f / std::max(0.001f, std::cos(light.inner_cone) - std::cos(light.outer_cone));
        const float offset = -std::cos(light.outer_cone) * scale;
        const float a = std::clamp(glm::dot(light.direction, -wi) * scale + offset, 0.0f, 1.0f);
        falloff = a * a;
    }
    return rho_over_pi * light.intensity * falloff * std::max(0.0f, glm::dot(n, wi)) / dist2;
}

scene::Light example_point_light() {
    scene::Light l;
    l.type = scene::LightType::Point;
    l.position = Vec3(-0.4f, 1.2f, 0.3f);
    l.intensity = Rgb(3.0f, 2.0f, 1.0f);
    return l;
}

scene::Light example_spot_light() {
    scene::Light l;
    l.type = scene::LightType::Spot;
    l.position = Vec3(0.3f, 1.0f, 0.0f);
    l.direction = glm::normalize(Vec3(0.2f, -1.0f, 0.1f));
    l.inner_cone = 0.3f;
    l.outer_cone = 0.6f;
    l.intensity = Rgb(4.0f);
    return l;
}

scene::Light example_directional_light() {
    scene::Light l;
    l.type = scene::LightType::Directional;
    l.direction = glm::normalize(Vec3(0.5f, -1.0f, 0.25f));
    l.intensity = Rgb(2.0f);
    return l;
}

}  // namespace mvpl::test
