#include "engine/scene/mitsuba/transform.h"

#include <cmath>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "engine/scene/camera.h"
#include "engine/scene/mitsuba/properties.h"

namespace mvpl::scene::mitsuba {

namespace {

// A vector given as value="x, y, z" or as x, y, z attributes (each defaulting to `fallback`).
DVec3 read_vector(const Context& ctx, pugi::xml_node e, const char* value, double fallback) {
    if (e.attribute(value)) {
        const std::vector<double> v = ctx.numbers(e, value);
        if (v.size() == 1) return DVec3(v[0]);
        if (v.size() != 3) ctx.fail(e, std::string(value) + " needs 1 or 3 numbers");
        return DVec3(v[0], v[1], v[2]);
    }
    DVec3 out(fallback);
    const char* axes[3] = {"x", "y", "z"};
    for (int i = 0; i < 3; ++i) {
        if (e.attribute(axes[i])) out[i] = ctx.number(e, axes[i]);
    }
    return out;
}

DVec3 read_triple(const Context& ctx, pugi::xml_node e, const char* attribute) {
    const std::vector<double> v = ctx.numbers(e, attribute);
    if (v.size() != 3) ctx.fail(e, std::string(attribute) + " needs 3 numbers");
    return DVec3(v[0], v[1], v[2]);
}

DMat4 look_at(const Context& ctx, pugi::xml_node e) {
    const DVec3 origin = read_triple(ctx, e, "origin");
    const DVec3 target = read_triple(ctx, e, "target");
    const DVec3 dir = target - origin;
    if (!(glm::length(dir) > 0.0)) ctx.fail(e, "lookat: the origin is the target");
    const DVec3 d = glm::normalize(dir);
    DVec3 up = e.attribute("up") ? read_triple(ctx, e, "up") : DVec3(0.0);
    if (!e.attribute("up")) {
        // Mitsuba's coordinate_system(d): any vector orthogonal to the view.
        up = std::abs(d.x) > std::abs(d.z) ? DVec3(-d.y, d.x, 0.0) : DVec3(0.0, -d.z, d.y);
    }
    const DVec3 left = glm::cross(up, d);
    if (!spans_camera_frame(up, d))
        ctx.fail(e, "lookat: up is zero or parallel to the view direction");
    const DVec3 l = glm::normalize(left);
    const DVec3 u = glm::cross(d, l);
    DMat4 m(1.0);
    m[0] = glm::dvec4(l, 0.0);
    m[1] = glm::dvec4(u, 0.0);
    m[2] = glm::dvec4(d, 0.0);
    m[3] = glm::dvec4(origin, 1.0);
    return m;
}

DMat4 one_step(const Context& ctx, pugi::xml_node e) {
    const std::string tag = e.name();
    if (tag == "translate") {
        DMat4 m(1.0);
        m[3] = glm::dvec4(read_vector(ctx, e, "value", 0.0), 1.0);
        return m;
    }
    if (tag == "scale") {
        const DVec3 s = read_vector(ctx, e, "value", 1.0);
        DMat4 m(1.0);
        m[0][0] = s.x;
        m[1][1] = s.y;
        m[2][2] = s.z;
        return m;
    }
    if (tag == "rotate") {
        const DVec3 axis = read_vector(ctx, e, "value", 0.0);
        if (!(glm::length(axis) > 0.0)) ctx.fail(e, "rotate: the axis is zero");
        const double angle = ctx.number(e, "angle") * (std::acos(-1.0) / 180.0);
        return glm::rotate(DMat4(1.0), angle, glm::normalize(axis));
    }
    if (tag == "matrix") {
        const std::vector<double> v = ctx.numbers(e, "value");
        DMat4 m(1.0);
        if (v.size() == 16) {
            for (int r = 0; r < 4; ++r)
                for (int c = 0; c < 4; ++c)
                    m[c][r] = v[size_t(r * 4 + c)];
        } else if (v.size() == 9) {
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 3; ++c)
                    m[c][r] = v[size_t(r * 3 + c)];
        } else {
            ctx.fail(e, "matrix needs 16 (or 9) numbers, not " + std::to_string(v.size()));
        }
        return m;
    }
    if (tag == "lookat") return look_at(ctx, e);
    ctx.fail(e, "<" + tag + "> is not a transform (translate, rotate, scale, matrix, lookat)");
}

}  // namespace

DMat4 read_transform(const Context& ctx, pugi::xml_node transform) {
    DMat4 m(1.0);
    for (pugi::xml_node step : ctx.xml().children(transform))
        m = one_step(ctx, step) * m;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!(std::abs(m[c][r]) <= 1e15)) ctx.fail(transform, "the transform overflows");
    return m;
}

DMat4 object_transform(const Context& ctx, pugi::xml_node object, const char* name) {
    const pugi::xml_node t = ctx.property(object, name);
    if (!t) return DMat4(1.0);
    if (std::string(t.name()) != "transform")
        ctx.fail(t, std::string("'") + name + "' must be a <transform>");
    return read_transform(ctx, t);
}

}  // namespace mvpl::scene::mitsuba
