#include "engine/scene/mitsuba/sensor.h"

#include <cmath>

#include "engine/scene/camera.h"
#include "engine/scene/mitsuba/aov_integrator.h"
#include "engine/scene/mitsuba/properties.h"
#include "engine/scene/mitsuba/transform.h"
#include "engine/scene/scene_range.h"

namespace mvpl::scene::mitsuba {

namespace {

// Mitsuba's film defaults (hdrfilm: 768 × 576).
constexpr int kDefaultWidth = 768, kDefaultHeight = 576;
constexpr int kMaxFilmSide = 16384;

void read_film(Context& ctx, pugi::xml_node film, int& width, int& height) {
    width = ctx.get_int(film, "width", kDefaultWidth);
    height = ctx.get_int(film, "height", kDefaultHeight);
    if (width < 1 || height < 1 || width > kMaxFilmSide || height > kMaxFilmSide)
        ctx.fail(film, "film size " + std::to_string(width) + "x" + std::to_string(height) +
                           " is outside 1..16384");
    for (pugi::xml_node f : ctx.objects(film, "rfilter")) {
        const std::string type = f.attribute("type").as_string();
        if (type != "box")
            ctx.warn(f, "rfilter '" + type + "' is dropped: mvpl's pixels are box-filtered");
    }
}

// The vertical field of view (radians) of Mitsuba's `fov` along `axis` for a width × height film.
double vertical_fov(Context& ctx, pugi::xml_node sensor, int width, int height) {
    const double pi = std::acos(-1.0);
    std::string axis = ctx.get_string(sensor, "fov_axis", "x");
    double fov = 0.0;
    if (ctx.property(sensor, "fov")) {
        fov = ctx.get_float(sensor, "fov", 0.0f);
    } else {
        // focal_length in 35 mm film equivalent ("50mm"), measured on the diagonal.
        std::string focal = ctx.get_string(sensor, "focal_length", "50mm");
        if (focal.ends_with("mm")) focal.resize(focal.size() - 2);
        char* end = nullptr;
        const double f = std::strtod(focal.c_str(), &end);
        if (*end != '\0' || !(f > 0.0) || !std::isfinite(f))
            ctx.fail(sensor, "focal_length '" + focal + "' is not a length in mm");
        fov = 2.0 * std::atan(std::hypot(36.0, 24.0) / (2.0 * f)) * 180.0 / pi;
        axis = "diagonal";
    }
    if (!(fov > 0.0 && fov < 180.0)) ctx.fail(sensor, "fov must be in (0, 180) degrees");
    const double t = std::tan(fov * pi / 360.0);
    const double w = width, h = height;
    if (axis == "smaller") axis = w <= h ? "x" : "y";
    if (axis == "larger") axis = w >= h ? "x" : "y";
    double tan_y = 0.0;
    if (axis == "x") {
        tan_y = t * h / w;
    } else if (axis == "y") {
        tan_y = t;
    } else if (axis == "diagonal") {
        tan_y = t * h / std::hypot(w, h);
    } else {
        ctx.fail(ctx.property(sensor, "fov_axis"),
                 "fov_axis '" + axis + "' is not x, y, smaller, larger or diagonal");
    }
    const double yfov = 2.0 * std::atan(tan_y);
    if (!(yfov >= kMinYfov && yfov <= kMaxYfov))
        ctx.fail(sensor, "the vertical field of view is out of range");
    return yfov;
}

}  // namespace

void add_sensor(Context& ctx, pugi::xml_node sensor) {
    const std::string type = sensor.attribute("type").as_string();
    if (type == "thinlens") {
        ctx.warn(sensor, "thinlens is rendered as a pinhole (no depth of field)");
    } else if (type != "perspective") {
        ctx.fail(sensor, "sensor type '" + type + "' is not supported");
    }
    int width = kDefaultWidth, height = kDefaultHeight;
    const std::vector<pugi::xml_node> films = ctx.objects(sensor, "film");
    if (!films.empty()) read_film(ctx, films.front(), width, height);
    for (pugi::xml_node s : ctx.objects(sensor, "sampler"))
        ctx.warn(s, "sampler '" + std::string(s.attribute("type").as_string()) +
                        "' is dropped: --spp (reference) and --vpls (render) set the effort");
    const DMat4 m = object_transform(ctx, sensor);
    // Mitsuba's camera looks down +Z with +X to the left; mvpl's (glTF's) down −Z with +X to the
    // right: the same frame turned half round Y. The columns' lengths (a scale) are dropped.
    DVec3 left(m[0]), up(m[1]), forward(m[2]);
    if (!(glm::length(left) > 0.0 && glm::length(up) > 0.0 && glm::length(forward) > 0.0))
        ctx.fail(sensor, "the sensor's to_world is singular");
    if (!spans_camera_frame(up, forward))
        ctx.fail(sensor, "the sensor's up is parallel to its view direction (a degenerate frame)");
    if (glm::dot(glm::cross(left, up), forward) < 0.0)
        ctx.warn(sensor, "the sensor's to_world mirrors the image; mvpl renders it unmirrored");
    forward = glm::normalize(forward);
    up = glm::normalize(up - forward * glm::dot(up, forward));
    const DVec3 right = glm::cross(forward, up);
    Camera camera;
    camera.camera_to_world =
        Mat4(glm::dvec4(right, 0.0), glm::dvec4(up, 0.0), glm::dvec4(-forward, 0.0), m[3]);
    for (int c = 0; c < 3; ++c) {
        if (!(std::abs(m[3][c]) <= kMaxCoordinate))
            ctx.fail(sensor, "the sensor lies out of range");
    }
    camera.yfov = float(vertical_fov(ctx, sensor, width, height));
    const float near_clip = ctx.get_float(sensor, "near_clip", 0.01f);
    if (!(near_clip > 0.0f)) ctx.fail(sensor, "near_clip must be positive");
    camera.znear = near_clip;
    Scene& scene = ctx.scene();
    if (scene.cameras.empty()) {
        scene.camera = camera;
        scene.has_camera = true;
        scene.film_width = width;
        scene.film_height = height;
    }
    scene.cameras.push_back(camera);
}

namespace {

// Mitsuba 0.6's `vpl` (src/integrators/vpl/vpl.cpp): maxDepth (default 5), shadowMapResolution
// (default 512) and clamping (default 0.1), upgraded to snake_case as every 0.x name.
void read_vpl_integrator(Context& ctx, pugi::xml_node integrator) {
    Scene& scene = ctx.scene();
    const int depth = ctx.get_int(integrator, "max_depth", 5);
    if (depth == 0 || depth < -1)
        ctx.fail(ctx.property(integrator, "max_depth"),
                 "maxDepth " + std::to_string(depth) + " is not a depth (1.., or -1)");
    scene.max_depth = std::min(depth, 1024);
    // The range --shadow-res takes.
    const int resolution = ctx.get_int(integrator, "shadow_map_resolution", 512);
    if (resolution < 4 || resolution > 4096)
        ctx.fail(ctx.property(integrator, "shadow_map_resolution"),
                 "shadowMapResolution " + std::to_string(resolution) + " is not in 4..4096");
    scene.shadow_resolution = resolution;
    const float clamping = ctx.get_float(integrator, "clamping", 0.1f);
    if (!(clamping >= 0.0f && clamping <= 1.0f))
        ctx.fail(ctx.property(integrator, "clamping"), "clamping must be in [0, 1]");
    scene.vpl_clamping = clamping;
}

}  // namespace

void read_integrator(Context& ctx, pugi::xml_node integrator) {
    const std::string type = integrator.attribute("type").as_string();
    if (type == "aov") {
        read_aov_integrator(ctx, integrator);
        return;
    }
    if (type == "direct") {
        ctx.scene().max_depth = 2;
        return;
    }
    if (type == "vpl") {
        read_vpl_integrator(ctx, integrator);
        return;
    }
    if (type != "path" && type != "volpath" && type != "volpathmis" && type != "prb")
        ctx.warn(integrator, "integrator '" + type + "' is rendered as a path tracer");
    const int depth = ctx.get_int(integrator, "max_depth", -1);
    if (depth == 0 || depth < -1)
        ctx.fail(ctx.property(integrator, "max_depth"),
                 "max_depth " + std::to_string(depth) + " is not a depth (1.., or -1)");
    ctx.scene().max_depth = std::min(depth, 1024);
    for (pugi::xml_node inner : ctx.objects(integrator, "integrator"))
        read_integrator(ctx, inner);
}

}  // namespace mvpl::scene::mitsuba
