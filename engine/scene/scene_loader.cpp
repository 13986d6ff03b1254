#include "engine/scene/scene_loader.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numeric>

#include "engine/core/error.h"
#include "engine/core/file_extension.h"
#include "engine/core/regular_file.h"
#include "engine/scene/camera.h"
#include "engine/scene/obj_loader.h"
#include "engine/scene/ply_loader.h"
#include "engine/scene/scene_range.h"

namespace mvpl::scene {

namespace {

// Unit normals for every vertex, or false when one is missing, zero or not finite.
bool normalise_normals(Mesh& mesh) {
    if (mesh.normals.size() != mesh.positions.size()) return false;
    for (Vec3& n : mesh.normals) {
        const float length = glm::length(n);
        if (!(length > 0.0f) || !std::isfinite(length)) return false;
        n /= length;
    }
    return true;
}

// Every triangle gets its own three vertices carrying its face normal (computed in double so
// that tiny triangles do not underflow); a degenerate triangle gets +Z, as in the glTF loader.
void make_flat(Mesh& mesh) {
    std::vector<Vec3> positions(mesh.indices.size());
    std::vector<Vec2> uv0(mesh.uv0.empty() ? 0 : mesh.indices.size());
    for (size_t i = 0; i < mesh.indices.size(); ++i) {
        positions[i] = mesh.positions[mesh.indices[i]];
        if (!uv0.empty()) uv0[i] = mesh.uv0[mesh.indices[i]];
    }
    mesh.positions = std::move(positions);
    mesh.uv0 = std::move(uv0);
    mesh.normals.resize(mesh.positions.size());
    std::iota(mesh.indices.begin(), mesh.indices.end(), 0u);
    for (size_t t = 0; t < mesh.indices.size(); t += 3) {
        const DVec3 a(mesh.positions[t]);
        const DVec3 n =
            glm::cross(DVec3(mesh.positions[t + 1]) - a, DVec3(mesh.positions[t + 2]) - a);
        const double length = glm::length(n);
        const Vec3 unit =
            length > 0.0 && std::isfinite(length) ? Vec3(n / length) : Vec3(0.0f, 0.0f, 1.0f);
        mesh.normals[t] = mesh.normals[t + 1] = mesh.normals[t + 2] = unit;
    }
}

}  // namespace

namespace {

Scene load_by_extension(const std::string& path, const LoadOptions& options) {
    require_regular_file(path);
    const std::string extension = lower_extension(path);
    if (extension == ".xml") return load_mitsuba(path, options);
    if (extension == ".gltf" || extension == ".glb") return load_gltf(path);
    if (extension == ".ply") return load_ply(path);
    if (extension == ".obj") return load_obj(path);
    throw InputError(path, "unsupported scene format" +
                               (extension.empty() ? std::string(" (no file extension)")
                                                  : " '" + extension + "'") +
                               "; expected .gltf, .glb, .ply, .obj or .xml");
}

}  // namespace

Scene load_scene(const std::string& path, const LoadOptions& options) {
    Scene scene = load_by_extension(path, options);
    check_scene_size(scene, path);
    return scene;
}

Material default_mesh_material() {
    Material m;
    m.name = "default";
    m.base_color = Rgb(0.5f);
    m.metallic = 0.0f;
    m.roughness = 1.0f;
    m.specular = 0.0f;
    // Mesh files say nothing about sidedness, and scanned meshes' windings are unreliable.
    m.double_sided = true;
    return m;
}

Scene mesh_scene(const std::string& path, std::vector<Mesh> meshes,
                 std::vector<Material> materials) {
    Scene scene;
    scene.path = path;
    for (Mesh& mesh : meshes) {
        if (mesh.indices.empty()) continue;
        if (!normalise_normals(mesh)) make_flat(mesh);
        scene.meshes.push_back(std::move(mesh));
    }
    if (scene.meshes.empty()) throw InputError(path, "no triangle geometry");
    scene.materials = std::move(materials);
    scene.camera = frame_bounds(scene.bounds());
    scene.has_camera = false;
    check_emitted_power(
        scene, [](int light) { return "light " + std::to_string(light); },
        [&](int material) { return "material '" + scene.materials[size_t(material)].name + "'"; },
        [&](const std::string& what) { throw InputError(path, what); });
    return scene;
}

}  // namespace mvpl::scene
