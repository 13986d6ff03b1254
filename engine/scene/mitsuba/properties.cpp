#include "engine/scene/mitsuba/properties.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "engine/core/image.h"
#include "engine/scene/mitsuba/spectrum.h"

namespace mvpl::scene::mitsuba {

namespace {

bool is_blank(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == ',';
}

}  // namespace

void Context::warn(pugi::xml_node at, const std::string& what) {
    // Scene::warnings are printed after the scene's path: a line of the scene file itself says
    // only its line number, one of an included file its FILE:LINE.
    std::string where = m_xml.where(at);
    if (where.starts_with(m_xml.path() + ":"))
        where = "line " + where.substr(m_xml.path().size() + 1);
    const std::string line = where + ": " + what;
    if (std::find(m_scene.warnings.begin(), m_scene.warnings.end(), line) == m_scene.warnings.end())
        m_scene.warnings.push_back(line);
}

void Context::index_ids(pugi::xml_node node) {
    for (pugi::xml_node child : m_xml.children(node)) {
        const std::string tag = child.name();
        if (tag == "ref") continue;
        if (pugi::xml_attribute id = child.attribute("id")) m_ids[id.value()] = child;
        index_ids(child);
    }
}

pugi::xml_node Context::lookup(pugi::xml_node at, const std::string& id) const {
    const auto found = m_ids.find(id);
    if (found == m_ids.end()) fail(at, "unknown reference '" + id + "'");
    return found->second;
}

pugi::xml_node Context::dereference(pugi::xml_node node) const {
    if (std::string(node.name()) != "ref") return node;
    return lookup(node, node.attribute("id").as_string());
}

pugi::xml_node Context::property(pugi::xml_node object, const std::string& name) const {
    for (pugi::xml_node child : m_xml.children(object)) {
        if (child.attribute("name").as_string() != name) continue;
        return dereference(child);
    }
    return pugi::xml_node();
}

std::vector<pugi::xml_node> Context::objects(pugi::xml_node object, const std::string& tag) const {
    std::vector<pugi::xml_node> out;
    for (pugi::xml_node child : m_xml.children(object)) {
        const pugi::xml_node target = dereference(child);
        if (target.name() == tag) out.push_back(target);
    }
    return out;
}

std::vector<double> Context::numbers(pugi::xml_node at, const char* attribute) const {
    const pugi::xml_attribute a = at.attribute(attribute);
    if (!a) fail(at, "<" + std::string(at.name()) + "> has no '" + attribute + "' attribute");
    const std::string text = a.value();
    std::vector<double> out;
    size_t i = 0;
    while (i < text.size()) {
        if (is_blank(text[i])) {
            ++i;
            continue;
        }
        size_t end = i;
        while (end < text.size() && !is_blank(text[end]))
            ++end;
        double value = 0.0;
        const char* first = text.data() + i;
        const char* last = text.data() + end;
        if (*first == '$')
            fail(at, "undefined parameter '" + std::string(first, last) + "' (give it with -D " +
                         std::string(first + 1, last) + "=VALUE or a <default>)");
        if (*first == '+' && last - first > 1) ++first;  // from_chars takes no plus sign
        const auto [ptr, ec] = std::from_chars(first, last, value);
        if (ec != std::errc() || ptr != last || !std::isfinite(value))
            fail(at, std::string(attribute) + " '" + std::string(first, last) +
                         "' is not a finite number");
        out.push_back(value);
        i = end;
    }
    if (out.empty()) fail(at, std::string(attribute) + " is empty");
    return out;
}

double Context::number(pugi::xml_node at, const char* attribute) const {
    const std::vector<double> v = numbers(at, attribute);
    if (v.size() != 1) fail(at, std::string(attribute) + " must be one number");
    return v[0];
}

float Context::get_float(pugi::xml_node object, const std::string& name, float fallback) const {
    const pugi::xml_node p = property(object, name);
    if (!p) return fallback;
    const std::string tag = p.name();
    if (tag != "float" && tag != "integer")
        fail(p, "'" + name + "' must be a float, not <" + tag + ">");
    const double v = number(p, "value");
    if (std::abs(v) > 1e15) fail(p, "'" + name + "' = " + std::to_string(v) + " is out of range");
    return float(v);
}

int Context::get_int(pugi::xml_node object, const std::string& name, int fallback) const {
    const pugi::xml_node p = property(object, name);
    if (!p) return fallback;
    const double v = number(p, "value");
    if (v != std::floor(v) || std::abs(v) > 1e9) fail(p, "'" + name + "' must be an integer");
    return int(v);
}

bool Context::get_bool(pugi::xml_node object, const std::string& name, bool fallback) const {
    const pugi::xml_node p = property(object, name);
    if (!p) return fallback;
    const std::string v = p.attribute("value").as_string();
    if (v == "true" || v == "1") return true;
    if (v == "false" || v == "0") return false;
    fail(p, "'" + name + "' must be true or false, not '" + v + "'");
}

std::string Context::get_string(pugi::xml_node object, const std::string& name,
                                const std::string& fallback) const {
    const pugi::xml_node p = property(object, name);
    if (!p) return fallback;
    return p.attribute("value").as_string();
}

Vec3 Context::get_point(pugi::xml_node object, const std::string& name,
                        const Vec3& fallback) const {
    const pugi::xml_node p = property(object, name);
    if (!p) return fallback;
    if (p.attribute("value")) {
        const std::vector<double> v = numbers(p, "value");
        if (v.size() == 1) return Vec3(float(v[0]));
        if (v.size() != 3) fail(p, "'" + name + "' needs 3 numbers");
        return Vec3(float(v[0]), float(v[1]), float(v[2]));
    }
    Vec3 out(0.0f);
    const char* axes[3] = {"x", "y", "z"};
    for (int i = 0; i < 3; ++i) {
        if (p.attribute(axes[i])) out[i] = float(number(p, axes[i]));
    }
    return out;
}

std::optional<Rgb> Context::get_color(pugi::xml_node object, const std::string& name) const {
    const pugi::xml_node p = property(object, name);
    if (!p) return std::nullopt;
    return color_value(*this, p);
}

Rgb color_value(const Context& ctx, pugi::xml_node e) {
    const std::string tag = e.name();
    Rgb out(0.0f);
    if (tag == "srgb" && std::string(e.attribute("value").as_string()).starts_with("#")) {
        const std::string hex = e.attribute("value").as_string();
        unsigned value = 0;
        const auto [ptr, ec] = std::from_chars(hex.data() + 1, hex.data() + hex.size(), value, 16);
        if (hex.size() != 7 || ec != std::errc() || ptr != hex.data() + hex.size())
            ctx.fail(e, "srgb value '" + hex + "' is not #rrggbb");
        out = Rgb(float((value >> 16) & 255u), float((value >> 8) & 255u), float(value & 255u)) /
              255.0f;
    } else if (tag == "rgb" || tag == "srgb" || tag == "float") {
        const std::vector<double> v = ctx.numbers(e, "value");
        if (v.size() == 1) {
            out = Rgb(float(v[0]));
        } else if (v.size() == 3 && tag != "float") {
            out = Rgb(float(v[0]), float(v[1]), float(v[2]));
        } else {
            ctx.fail(e, "<" + tag + "> needs 1 or 3 numbers");
        }
    } else if (tag == "spectrum") {
        const std::string text = e.attribute("value").as_string();
        if (text.find(':') == std::string::npos) {
            const std::vector<double> v = ctx.numbers(e, "value");
            if (v.size() != 1) ctx.fail(e, "a spectrum needs one value or wavelength:value pairs");
            out = Rgb(float(v[0]));
        } else {
            out = spectrum_to_rgb(ctx, e, text);
        }
    } else {
        ctx.fail(e, "expected a colour (rgb, srgb, spectrum or float), not <" + tag + ">");
    }
    for (int c = 0; c < 3; ++c) {
        if (!(std::abs(out[c]) <= 1e15f)) ctx.fail(e, "colour component out of range");
    }
    if (tag == "srgb")
        out = Rgb(srgb_to_linear(out.r), srgb_to_linear(out.g), srgb_to_linear(out.b));
    return out;
}

}  // namespace mvpl::scene::mitsuba
