#include "tests/support/glass_slab.h"

#include <cmath>

#include "engine/scene/camera.h"
#include "tests/support/scene_builder.h"

namespace mvpl::test {

namespace {

scene::Texture checker() {
    constexpr int kCells = 8;
    scene::Texture t;
    t.name = "checker";
    t.width = t.height = kCells;
    t.filter = scene::Filter::Linear;
    for (int y = 0; y < kCells; ++y) {
        for (int x = 0; x < kCells; ++x) {
            const float v = (x + y) % 2 == 0 ? 0.8f : 0.2f;
            t.texels.push_back(Vec4(v, v, v, 1.0f));
        }
    }
    return t;
}

}  // namespace

scene::Scene make_glass_slab(const Rgb& tint, float thickness) {
    scene::Scene s;
    scene::Material wall = diffuse_material(Rgb(1.0f, 0.9f, 0.7f));
    wall.base_color_texture.texture = 0;
    scene::Material glass;
    glass.base_color = tint;
    glass.metallic = 0.0f;
    glass.roughness = 0.0f;
    glass.ior = 1.5f;
    glass.transmission = 1.0f;
    glass.double_sided = true;
    glass.thickness = thickness;
    s.textures = {checker()};
    s.materials = {wall,
                   diffuse_material(Rgb(0.75f)),
                   diffuse_material(Rgb(0.1f)),
                   diffuse_material(Rgb(0.0f)),
                   diffuse_material(Rgb(0.0f)),
                   glass};
    s.materials[3].emissive = Rgb(8.0f);
    // Walls facing in (make_quad's front face is along cross(a, b)).
    s.meshes.push_back(make_quad(Vec3(-1, -1, -1), Vec3(2, 0, 0), Vec3(0, 2, 0), 0));  // back
    s.meshes.push_back(make_quad(Vec3(-1, -1, -1), Vec3(0, 0, 2), Vec3(2, 0, 0), 1));  // floor
    s.meshes.push_back(make_quad(Vec3(-1, 1, -1), Vec3(2, 0, 0), Vec3(0, 0, 2), 1));   // ceiling
    s.meshes.push_back(make_quad(Vec3(-1, -1, -1), Vec3(0, 2, 0), Vec3(0, 0, 2), 2));  // left
    s.meshes.push_back(make_quad(Vec3(1, -1, -1), Vec3(0, 0, 2), Vec3(0, 2, 0), 2));   // right
    s.meshes.push_back(
        make_quad(Vec3(-0.4f, 0.99f, -0.9f), Vec3(0.8f, 0, 0), Vec3(0, 0, 0.5f), 3));  // light
    const float h = kGlassSheetHalf;
    const float z = kGlassSheetZ;
    const int g = kGlassMaterial;
    // The sheet (or the box's front), facing +Z.
    s.meshes.push_back(make_quad(Vec3(-h, -h, z), Vec3(2 * h, 0, 0), Vec3(0, 2 * h, 0), g));
    if (thickness > 0.0f) {
        const float d = thickness;
        const float b = z - d;
        s.meshes.push_back(make_quad(Vec3(-h, -h, b), Vec3(0, 2 * h, 0), Vec3(2 * h, 0, 0), g));
        s.meshes.push_back(make_quad(Vec3(-h, -h, b), Vec3(0, 0, d), Vec3(0, 2 * h, 0), g));
        s.meshes.push_back(make_quad(Vec3(h, -h, b), Vec3(0, 2 * h, 0), Vec3(0, 0, d), g));
        s.meshes.push_back(make_quad(Vec3(-h, -h, b), Vec3(2 * h, 0, 0), Vec3(0, 0, d), g));
        s.meshes.push_back(make_quad(Vec3(-h, h, b), Vec3(0, 0, d), Vec3(2 * h, 0, 0), g));
    }
    s.camera = look_at(Vec3(0.0f, 0.0f, 3.0f), Vec3(0.0f, 0.0f, -1.0f), 0.6f);
    s.has_camera = true;
    return s;
}

bool through_glass_sheet(const scene::Camera& camera, int size, int x, int y, float margin,
                         float* cos_theta) {
    const scene::CameraRay cr =
        scene::generate_camera_ray(camera, size, size, Vec2(float(x) + 0.5f, float(y) + 0.5f));
    if (!(cr.direction.z < 0.0f)) return false;
    const float t = (kGlassSheetZ - cr.origin.z) / cr.direction.z;
    const Vec3 p = cr.origin + t * cr.direction;
    const float limit = kGlassSheetHalf - margin;
    if (std::abs(p.x) > limit || std::abs(p.y) > limit) return false;
    if (cos_theta) *cos_theta = -glm::normalize(cr.direction).z;
    return true;
}

}  // namespace mvpl::test
