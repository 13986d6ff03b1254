// libFuzzer target for the scene loaders (glTF .gltf/.glb, PLY, OBJ, Mitsuba XML with its
// <include> and <default>) and the camera set-up: whatever the bytes, a load either succeeds with
// a scene whose every position lies within engine/scene/scene_range.h's kMaxCoordinate, every
// light and material factor within kMaxFactor and every index in range, and whose every camera
// (scene/camera_choice.h) makes finite rays, or throws InputError. Anything else — a crash, a
// sanitizer report, another exception, a hang — is a finding. The format is chosen from the bytes
// as a user's file extension would choose it: the GLB magic, "ply", a '{' (JSON), a '<' (Mitsuba
// XML) or else OBJ. tests/fuzz/README.md says how to run it.
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "engine/core/error.h"
#include "engine/scene/camera.h"
#include "engine/scene/camera_choice.h"
#include "engine/scene/scene_loader.h"
#include "engine/scene/scene_range.h"

namespace {

std::string extension_of(const uint8_t* data, size_t size) {
    const auto starts = [&](const char* prefix) {
        const size_t n = std::char_traits<char>::length(prefix);
        return size >= n &&
               std::char_traits<char>::compare(reinterpret_cast<const char*>(data), prefix, n) == 0;
    };
    if (starts("glTF")) return ".glb";
    if (starts("ply")) return ".ply";
    for (size_t i = 0; i < size; ++i) {
        const char c = char(data[i]);
        if (c == ' ' || c == '\t' || c == '\n' || c == '\r') continue;
        if (c == '<') return ".xml";
        return c == '{' ? ".gltf" : ".obj";
    }
    return ".obj";
}

// One file per process and format, rewritten for every input (the loaders read paths), named
// scene.EXT in a folder of this process's own: a Mitsuba input may `<include
// filename="scene.xml"/>` itself, so that the seeds reach the include bounds (xml_files.cpp).
std::string write_input(const uint8_t* data, size_t size, const std::string& extension) {
    const char* tmp = std::getenv("TMPDIR");
    const std::string dir =
        std::string(tmp ? tmp : "/tmp") + "/mvpl-fuzz-" + std::to_string(getpid());
    static const bool made = mkdir(dir.c_str(), 0700) == 0 || errno == EEXIST;
    if (!made) std::abort();
    const std::string path = dir + "/scene" + extension;
    FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) std::abort();
    if (size > 0 && std::fwrite(data, 1, size, f) != size) std::abort();
    std::fclose(f);
    return path;
}

bool within(float value, double limit) {
    return std::abs(double(value)) <= limit;  // false for NaN
}

bool within(const mvpl::Vec3& v, double limit) {
    return within(v.x, limit) && within(v.y, limit) && within(v.z, limit);
}

void check(const mvpl::scene::Scene& scene) {
    using mvpl::scene::kMaxCoordinate;
    using mvpl::scene::kMaxFactor;
    for (const mvpl::scene::Mesh& mesh : scene.meshes) {
        for (const mvpl::Vec3& p : mesh.positions) {
            if (!within(p, kMaxCoordinate)) std::abort();
        }
        for (const uint32_t i : mesh.indices) {
            if (i >= mesh.positions.size()) std::abort();
        }
        if (mesh.normals.size() != mesh.positions.size()) std::abort();
        if (mesh.material < 0 || size_t(mesh.material) >= scene.materials.size()) std::abort();
    }
    for (const mvpl::scene::Light& light : scene.lights) {
        if (!within(light.position, kMaxCoordinate) || !within(light.intensity, kMaxFactor)) {
            std::abort();
        }
    }
    for (const mvpl::scene::Material& m : scene.materials) {
        if (!within(m.emission(), kMaxFactor) || !within(m.base_color, kMaxFactor)) std::abort();
    }
    // A camera made to frame the bounds stands outside them, at most ≈6e9 for bounds at the
    // limit (scene/camera.h): still far inside Embree's margin (scene_range.h).
    if (!within(scene.camera.position(), 10.0 * kMaxCoordinate)) std::abort();
}

// The camera set-up of every command: the scene's camera and each of its cameras (--camera N)
// either is refused (InputError) or makes finite rays with unit directions across the film.
void check_cameras(const mvpl::scene::Scene& scene) {
    constexpr int kSize = 16;
    for (int index = -1; index < int(scene.cameras.size()); ++index) {
        mvpl::scene::CameraChoice choice;
        choice.index = index;
        const mvpl::scene::Camera camera = mvpl::scene::choose_camera(scene, choice);
        for (const mvpl::Vec2 film : {mvpl::Vec2(0.0f), mvpl::Vec2(kSize / 2), mvpl::Vec2(kSize)}) {
            const mvpl::scene::CameraRay ray =
                mvpl::scene::generate_camera_ray(camera, kSize, kSize, film);
            if (!within(ray.origin, 10.0 * mvpl::scene::kMaxCoordinate)) std::abort();
            if (!(std::abs(glm::length(ray.direction) - 1.0f) < 1e-3f)) std::abort();
        }
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string path = write_input(data, size, extension_of(data, size));
    try {
        const mvpl::scene::Scene scene = mvpl::scene::load_scene(path);
        check(scene);
        check_cameras(scene);
    } catch (const mvpl::InputError&) {
        // The expected refusal of a bad file.
    }
    std::remove(path.c_str());
    return 0;
}
