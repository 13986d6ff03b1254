#include "engine/scene/scene_range.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>
#include <vector>

#include "engine/core/error.h"

namespace mvpl::scene {
namespace {

double max_channel(const Rgb& c) {
    return std::max({double(c.r), double(c.g), double(c.b)});
}

std::string short_number(double value) {
    std::ostringstream out;
    out.precision(3);
    out << value;
    return out.str();
}

std::string flux_text(double watts) {
    return short_number(watts) + " W";
}

// Twice the triangle's area, in double: float cross products of large triangles overflow.
double twice_area(const Mesh& mesh, size_t triangle) {
    const uint32_t* idx = &mesh.indices[3 * triangle];
    const DVec3 a(mesh.positions[idx[0]]);
    return glm::length(
        glm::cross(DVec3(mesh.positions[idx[1]]) - a, DVec3(mesh.positions[idx[2]]) - a));
}

}  // namespace

void check_scene_size(const Scene& scene, const std::string& path) {
    const Bounds b = scene.bounds();
    if (b.empty()) return;
    const double size = glm::length(DVec3(b.hi) - DVec3(b.lo));
    if (size >= kMinSceneSize) return;
    throw InputError(path, "the scene's geometry is " + number_text(size) +
                               " m across, below the smallest size rendered right (" +
                               number_text(kMinSceneSize) + " m): scale it up");
}

std::string number_text(double value) {
    char text[64];
    // A double that is exactly a float (a position or factor already stored as one) reads as the
    // float's shortest form: "2e+12" rather than "1999999991808".
    const float narrow = float(value);
    const bool is_float = std::isfinite(narrow) && double(narrow) == value;
    const auto result =
        is_float ? std::to_chars(text, text + sizeof text, narrow, std::chars_format::general)
                 : std::to_chars(text, text + sizeof text, value, std::chars_format::general);
    return std::string(text, result.ptr);
}

void check_emitted_power(const Scene& scene, const EmitterName& name_light,
                         const EmitterName& name_material,
                         const std::function<void(const std::string&)>& fail) {
    struct Flux {
        std::string name;  // with how the flux comes about
        double watts = 0.0;
    };
    std::vector<Flux> emitters;
    // As light::LightSampler weighs them: a directional light lights a disk of the scene's
    // bounding-sphere radius.
    const double radius = 0.5 * double(scene.bounds().diagonal());
    for (size_t l = 0; l < scene.lights.size(); ++l) {
        const Light& light = scene.lights[l];
        const double intensity = max_channel(light.intensity);
        double watts = 0.0;
        switch (light.type) {
            case LightType::Point:
                watts = 4.0 * std::numbers::pi * intensity;
                break;
            case LightType::Spot:
                watts = 2.0 * std::numbers::pi * intensity *
                        (1.0 - 0.5 * (std::cos(double(light.inner_cone)) +
                                      std::cos(double(light.outer_cone))));
                break;
            case LightType::Directional:
                watts = std::numbers::pi * radius * radius * intensity;
                emitters.push_back({name_light(int(l)) + " (irradiance " + short_number(intensity) +
                                        " W/m^2 across the scene's bounding sphere of radius " +
                                        short_number(radius) + " m)",
                                    watts});
                continue;
        }
        emitters.push_back({name_light(int(l)), watts});
    }
    std::vector<double> area(scene.materials.size(), 0.0);
    for (const Mesh& mesh : scene.meshes) {
        if (mesh.material < 0 || size_t(mesh.material) >= area.size()) continue;
        if (!scene.materials[size_t(mesh.material)].is_emissive()) continue;
        for (size_t t = 0; t < mesh.triangle_count(); ++t)
            area[size_t(mesh.material)] += 0.5 * twice_area(mesh, t);
    }
    for (size_t m = 0; m < area.size(); ++m) {
        if (area[m] == 0.0) continue;
        const Material& material = scene.materials[m];
        const double radiance = max_channel(material.emission());
        // Lambertian emission from the front face: flux = π · A · L.
        emitters.push_back({name_material(int(m)) + " (radiance " + short_number(radiance) +
                                " W/(sr m^2) over " + short_number(area[m]) + " m^2)",
                            std::numbers::pi * area[m] * radiance});
    }

    double total = 0.0;
    const Flux* brightest = nullptr;
    for (const Flux& e : emitters) {
        total += e.watts;
        if (!brightest || e.watts > brightest->watts) brightest = &e;
    }
    // NaN (which the loaders' checks should make impossible) fails too.
    if (total <= kMaxPower || brightest == nullptr) return;
    const std::string limit = "more than the supported " + flux_text(kMaxPower);
    if (brightest->watts > kMaxPower) {
        fail(brightest->name + " emits " + flux_text(brightest->watts) + ", " + limit);
    }
    fail("the emitters emit " + flux_text(total) + " together (the most " + brightest->name + ", " +
         flux_text(brightest->watts) + "), " + limit);
}

}  // namespace mvpl::scene
