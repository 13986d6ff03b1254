#include "engine/scene/mitsuba/emitters.h"

#include <cmath>
#include <memory>

#include "engine/core/error.h"
#include "engine/scene/mitsuba/bitmap.h"
#include "engine/scene/mitsuba/properties.h"
#include "engine/scene/mitsuba/transform.h"
#include "engine/scene/scene_range.h"

namespace mvpl::scene::mitsuba {

namespace {

// Rows of the resampled map beyond which memory, not fidelity, decides (2^23 texels).
constexpr int kMaxEnvironmentRows = 2048;

Rgb color_or(Context& ctx, pugi::xml_node emitter, const char* name, const Rgb& fallback) {
    const pugi::xml_node p = ctx.property(emitter, name);
    if (!p) return fallback;
    if (std::string(p.name()) == "texture")
        ctx.fail(p, std::string("a textured '") + name + "' is not supported");
    const Rgb c = color_value(ctx, p);
    if (!(c.r >= 0.0f && c.g >= 0.0f && c.b >= 0.0f))
        ctx.fail(p, std::string(name) + " is negative");
    return c;
}

// Mitsuba's envmap radiance at local direction v: u = atan2(v.x, −v.z) / 2π (wrapped), v =
// acos(v.y) / π, bilinear between texel centres (wrapping in u, clamped in v).
Vec3 mitsuba_lookup(const Bitmap& b, const DVec3& v) {
    const double pi = std::acos(-1.0);
    double u = std::atan2(v.x, -v.z) / (2.0 * pi);
    u -= std::floor(u);
    const double t = std::acos(std::clamp(v.y, -1.0, 1.0)) / pi;
    const double x = u * b.width - 0.5, y = std::clamp(t * b.height - 0.5, 0.0, b.height - 1.0);
    const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
    const double fx = x - x0, fy = y - y0;
    const auto at = [&](int xi, int yi) {
        xi = ((xi % b.width) + b.width) % b.width;
        yi = std::clamp(yi, 0, b.height - 1);
        return DVec3(Vec3(b.texels[size_t(yi) * size_t(b.width) + size_t(xi)]));
    };
    return Vec3((at(x0, y0) * (1 - fx) + at(x0 + 1, y0) * fx) * (1 - fy) +
                (at(x0, y0 + 1) * (1 - fx) + at(x0 + 1, y0 + 1) * fx) * fy);
}

// The envmap resampled into mvpl's latitude-longitude orientation (environment.h) under
// `to_world`: each mvpl texel centre's direction looked up as Mitsuba does. Exact (a copy) when
// to_world turns about +Y by a multiple of 90° and the map is 2:1 with a width divisible by 4.
std::shared_ptr<const EnvironmentMap> resample(const Bitmap& b, const DMat4& to_world,
                                               const std::string& path) {
    auto map = std::make_shared<EnvironmentMap>();
    map->height = std::min(std::max(b.height, b.width / 2), kMaxEnvironmentRows);
    map->width = 2 * map->height;
    map->path = path;
    map->texels.resize(size_t(map->width) * size_t(map->height));
    const glm::dmat3 to_local = glm::inverse(glm::dmat3(to_world));
    Environment frame;
    for (int y = 0; y < map->height; ++y) {
        for (int x = 0; x < map->width; ++x) {
            const Vec2 uv((float(x) + 0.5f) / float(map->width),
                          (float(y) + 0.5f) / float(map->height));
            const DVec3 local = glm::normalize(to_local * DVec3(frame.uv_to_direction(uv)));
            map->texels[size_t(y) * size_t(map->width) + size_t(x)] = mitsuba_lookup(b, local);
        }
    }
    return map;
}

void set_environment(Context& ctx, pugi::xml_node emitter, Environment environment) {
    if (ctx.scene().environment.active())
        ctx.fail(emitter, "a second environment emitter (mvpl renders one)");
    ctx.scene().environment = std::move(environment);
}

}  // namespace

Rgb area_radiance(Context& ctx, pugi::xml_node emitter) {
    const std::string type = emitter.attribute("type").as_string();
    if (type != "area") ctx.fail(emitter, "a shape's emitter must be 'area', not '" + type + "'");
    return color_or(ctx, emitter, "radiance", Rgb(1.0f));
}

void add_emitter(Context& ctx, pugi::xml_node emitter) {
    const std::string type = emitter.attribute("type").as_string();
    const DMat4 to_world = object_transform(ctx, emitter);
    Light light;
    if (pugi::xml_attribute id = emitter.attribute("id")) light.name = id.value();
    const DVec3 forward = glm::dmat3(to_world) * DVec3(0.0, 0.0, 1.0);
    if (type == "point") {
        light.type = LightType::Point;
        light.intensity = color_or(ctx, emitter, "intensity", Rgb(1.0f));
        light.position = ctx.property(emitter, "position")
                             ? ctx.get_point(emitter, "position", Vec3(0.0f))
                             : Vec3(to_world[3]);
    } else if (type == "spot") {
        if (ctx.property(emitter, "texture"))
            ctx.fail(emitter, "a spot light with a texture is not supported");
        light.type = LightType::Spot;
        light.intensity = color_or(ctx, emitter, "intensity", Rgb(1.0f));
        light.position = Vec3(to_world[3]);
        const float cutoff = ctx.get_float(emitter, "cutoff_angle", 20.0f);
        const float beam = ctx.get_float(emitter, "beam_width", cutoff * 0.75f);
        if (!(cutoff > 0.0f && cutoff <= 180.0f && beam >= 0.0f && beam <= cutoff))
            ctx.fail(emitter, "spot needs 0 < beam_width ≤ cutoff_angle ≤ 180");
        // Mitsuba fades linearly in angle between them, glTF (and mvpl) smoothly in cosine.
        light.outer_cone = cutoff * kPi / 180.0f;
        light.inner_cone = beam * kPi / 180.0f;
        if (!(glm::length(forward) > 0.0)) ctx.fail(emitter, "the spot's to_world is singular");
        light.direction = Vec3(glm::normalize(forward));
    } else if (type == "directional") {
        light.type = LightType::Directional;
        light.intensity = color_or(ctx, emitter, "irradiance", Rgb(1.0f));
        const DVec3 d = ctx.property(emitter, "direction")
                            ? DVec3(ctx.get_point(emitter, "direction", Vec3(0.0f)))
                            : forward;
        if (!(glm::length(d) > 0.0)) ctx.fail(emitter, "the direction is zero");
        light.direction = Vec3(glm::normalize(d));
    } else if (type == "constant") {
        Environment e;
        e.radiance = color_or(ctx, emitter, "radiance", Rgb(1.0f));
        set_environment(ctx, emitter, std::move(e));
        return;
    } else if (type == "envmap") {
        const pugi::xml_node name = ctx.property(emitter, "filename");
        if (!name) ctx.fail(emitter, "envmap needs a filename");
        const std::string path = ctx.xml().resolve(name, name.attribute("value").as_string());
        Bitmap bitmap;
        try {
            bitmap = read_bitmap(path, false);
        } catch (const InputError& e) {
            ctx.fail(name, e.what());
        }
        if (std::abs(glm::determinant(glm::dmat3(to_world))) < 1e-12)
            ctx.fail(emitter, "the envmap's to_world is singular");
        Environment e;
        const float scale = ctx.get_float(emitter, "scale", 1.0f);
        if (!(scale >= 0.0f)) ctx.fail(emitter, "the envmap's scale is negative");
        e.radiance = Rgb(scale);
        e.map = resample(bitmap, to_world, path);
        set_environment(ctx, emitter, std::move(e));
        return;
    } else {
        ctx.fail(emitter, "emitter type '" + type + "' is not supported");
    }
    for (int c = 0; c < 3; ++c) {
        if (!(std::abs(light.position[c]) <= kMaxCoordinate))
            ctx.fail(emitter, "the emitter lies at " + number_text(light.position[c]) +
                                  ", beyond the supported magnitude " +
                                  number_text(kMaxCoordinate));
    }
    ctx.scene().lights.push_back(light);
}

}  // namespace mvpl::scene::mitsuba
