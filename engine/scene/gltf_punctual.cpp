#include "engine/scene/gltf_punctual.h"

#include <numbers>
#include <string>

#include "engine/scene/camera.h"
#include "engine/scene/gltf_value.h"
#include "engine/scene/scene_range.h"

namespace mvpl::scene::gltf {
namespace {

// Slack for π/2 written out in decimal.
constexpr double kAngleSlack = 1e-6;
// The G-buffer's reversed depth is znear / distance in float; GPUs flush subnormal floats to
// zero (the cleared depth, which no surface passes), so znear / distance must stay a normal
// float (≥ 1.2e-38) up to the largest distance in a scene (2√3 · kMaxCoordinate ≈ 3.5e11):
// znear ≥ 4.2e-27, here with margin.
constexpr double kMinZnear = 1e-20;

DVec3 unit(const DVec3& v, bool& ok) {
    const double length = glm::length(v);
    ok = length > 0.0 && std::isfinite(length);
    return ok ? v / length : v;
}

// The node's world position (a light's or a camera's), within kMaxCoordinate.
Vec3 placed_position(const Document& doc, int node, const DMat4& world, const std::string& what) {
    const DVec3 p(world[3]);
    for (int c = 0; c < 3; ++c) {
        if (!(std::abs(p[c]) <= kMaxCoordinate)) {
            doc.fail(indexed("nodes", size_t(node)) + " places " + what + " at " +
                     std::string(1, "xyz"[c]) + " = " + number_text(p[c]) +
                     ", beyond the supported magnitude " + number_text(kMaxCoordinate));
        }
    }
    return Vec3(p);
}

}  // namespace

std::optional<Light> node_light(const Document& doc, int node, const DMat4& world,
                                std::string* where) {
    const tinygltf::Node& gltf_node = doc.model.nodes[size_t(node)];
    const std::string node_name = "node " + std::to_string(node);
    const tinygltf::Value* ext =
        find_extension(doc, gltf_node.extensions, "KHR_lights_punctual", node_name);
    if (ext == nullptr) return std::nullopt;
    const tinygltf::Value* light_member = find_member(*ext, "light");
    if (light_member == nullptr) doc.fail(node_name + " KHR_lights_punctual has no light index");
    const int index = read_int(doc, light_member, -1, node_name + " KHR_lights_punctual light");
    const auto& lights = doc.model.lights;
    if (index < 0 || size_t(index) >= lights.size()) {
        doc.fail(node_name + " refers to light " + std::to_string(index) + ", but the file has " +
                 std::to_string(lights.size()) + " lights");
    }
    const tinygltf::Light& light = lights[size_t(index)];
    const std::string name = indexed("extensions.KHR_lights_punctual.lights", size_t(index));

    Light out;
    out.name = light.name.empty() ? "light " + std::to_string(index) : light.name;
    Rgb colour(1.0f);
    if (!light.color.empty()) {
        if (light.color.size() != 3) doc.fail(name + ".color must have 3 components");
        for (int i = 0; i < 3; ++i) {
            colour[i] = float(check_non_negative(doc, light.color[size_t(i)], kMaxFactor,
                                                 indexed(name + ".color", size_t(i))));
        }
    }
    // Photometric intensity taken 1:1 as radiometric (docs/design.md).
    const double intensity =
        check_non_negative(doc, light.intensity, kMaxFactor, name + ".intensity");
    const double brightest = intensity * double(max_component(colour));
    check_non_negative(doc, brightest, kMaxFactor, name + " color x intensity");
    out.intensity = colour * float(intensity);
    // The renderer does not cut lights off at `range` (0 is tinygltf's "absent", infinite).
    if (light.range < 0.0) {
        doc.fail(name + ".range is " + number_text(light.range) + ", which is negative");
    }

    if (light.type == "point") {
        out.type = LightType::Point;
    } else if (light.type == "directional") {
        out.type = LightType::Directional;
    } else if (light.type == "spot") {
        out.type = LightType::Spot;
        const double inner = light.spot.innerConeAngle;
        const double outer = light.spot.outerConeAngle;
        const bool valid = std::isfinite(inner) && std::isfinite(outer) && inner >= 0.0 &&
                           inner < outer && outer <= std::numbers::pi / 2 + kAngleSlack;
        if (!valid) {
            doc.fail(name + ".spot has invalid cone angles (inner " + number_text(inner) +
                     ", outer " + number_text(outer) + "); need 0 <= inner < outer <= pi/2");
        }
        out.inner_cone = float(inner);
        out.outer_cone = float(outer);
    } else {
        doc.fail(name + " has unknown type '" + light.type + "'");
    }

    out.position = placed_position(doc, node, world, name);
    bool ok = false;
    out.direction = Vec3(unit(-DVec3(world[2]), ok));  // the node's -Z
    if (!ok) doc.fail(node_name + " orients " + name + " with a degenerate transform");
    if (where) *where = name + " (on " + indexed("nodes", size_t(node)) + ")";
    return out;
}

std::optional<Camera> node_camera(const Document& doc, int node, const DMat4& world) {
    const tinygltf::Node& gltf_node = doc.model.nodes[size_t(node)];
    if (gltf_node.camera == -1) return std::nullopt;
    const std::string node_name = "node " + std::to_string(node);
    const auto& cameras = doc.model.cameras;
    if (gltf_node.camera < 0 || size_t(gltf_node.camera) >= cameras.size()) {
        doc.fail(node_name + " refers to camera " + std::to_string(gltf_node.camera) +
                 ", but the file has " + std::to_string(cameras.size()) + " cameras");
    }
    const tinygltf::Camera& camera = cameras[size_t(gltf_node.camera)];
    if (camera.type != "perspective") return std::nullopt;
    const std::string name = indexed("cameras", size_t(gltf_node.camera));
    const tinygltf::PerspectiveCamera& perspective = camera.perspective;
    const double yfov =
        check_between(doc, perspective.yfov, kMinYfov, kMaxYfov, name + ".perspective.yfov");
    const double znear = check_between(doc, perspective.znear, kMinZnear, kMaxCoordinate,
                                       name + ".perspective.znear");
    // zfar and aspectRatio are not used (the projection is infinite, --res sets the aspect), but
    // values the specification forbids are refused; 0 is tinygltf's "absent".
    if (perspective.zfar != 0.0 && !(perspective.zfar > znear)) {
        doc.fail(name + ".perspective.zfar is " + number_text(perspective.zfar) +
                 ", not beyond znear " + number_text(znear));
    }
    if (perspective.aspectRatio < 0.0) {
        doc.fail(name + ".perspective.aspectRatio is " + number_text(perspective.aspectRatio) +
                 ", which is negative");
    }

    // The camera frame is rigid: keep the viewing direction (-Z) exactly, then the up vector
    // (Y) as far as it is orthogonal to it; a mirroring node cannot mirror the image.
    bool z_ok = false;
    bool y_ok = false;
    const DVec3 z = unit(DVec3(world[2]), z_ok);
    const DVec3 y = unit(DVec3(world[1]) - glm::dot(DVec3(world[1]), z) * z, y_ok);
    if (!z_ok || !y_ok || !spans_camera_frame(DVec3(world[1]), DVec3(world[2])))
        doc.fail(node_name + " places " + name + " with a degenerate transform");
    const DVec3 x = glm::cross(y, z);

    Camera out;
    out.camera_to_world = Mat4(Vec4(Vec3(x), 0.0f), Vec4(Vec3(y), 0.0f), Vec4(Vec3(z), 0.0f),
                               Vec4(placed_position(doc, node, world, name), 1.0f));
    out.yfov = float(yfov);
    out.znear = float(znear);
    return out;
}

}  // namespace mvpl::scene::gltf
