#pragma once
// Reading a Mitsuba plugin's properties: `<float name="radius" value="2"/>` and its kin, typed,
// with Mitsuba's defaults, each value checked (finite, in range) and every complaint naming the
// element's FILE:LINE. Objects are found by id (`<ref id="…"/>`) in one table for the scene.
#include <pugixml.hpp>

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/color.h"
#include "engine/core/math.h"
#include "engine/scene/mitsuba/xml_files.h"
#include "engine/scene/scene.h"

namespace mvpl::scene::mitsuba {

// The state one load shares between the plugins' readers.
class Context {
public:
    Context(const XmlFiles& xml, Scene& scene) : m_xml(xml), m_scene(scene) {}

    const XmlFiles& xml() const { return m_xml; }
    Scene& scene() { return m_scene; }
    [[noreturn]] void fail(pugi::xml_node at, const std::string& what) const {
        m_xml.fail(at, what);
    }
    // One warning line, "FILE:LINE: what" (Scene::warnings); each text once.
    void warn(pugi::xml_node at, const std::string& what);

    // Records every element with an id (in the scene's children and nested objects).
    void index_ids(pugi::xml_node node);
    // The element an id names, or fails at `at`.
    pugi::xml_node lookup(pugi::xml_node at, const std::string& id) const;
    // `node` itself, or the element a <ref> names.
    pugi::xml_node dereference(pugi::xml_node node) const;

    // The property element named `name` of `object` (a <ref name=…> is followed), or null.
    pugi::xml_node property(pugi::xml_node object, const std::string& name) const;
    // The child objects of `object` with this tag (bsdf, emitter, texture, shape), <ref>s
    // followed.
    std::vector<pugi::xml_node> objects(pugi::xml_node object, const std::string& tag) const;

    float get_float(pugi::xml_node object, const std::string& name, float fallback) const;
    int get_int(pugi::xml_node object, const std::string& name, int fallback) const;
    bool get_bool(pugi::xml_node object, const std::string& name, bool fallback) const;
    std::string get_string(pugi::xml_node object, const std::string& name,
                           const std::string& fallback) const;
    Vec3 get_point(pugi::xml_node object, const std::string& name, const Vec3& fallback) const;
    // rgb, srgb (numbers or #rrggbb), a single-valued spectrum, a float, or a spectrum of
    // wavelength:value pairs (projected onto linear Rec.709 through the CIE 1931 observer).
    std::optional<Rgb> get_color(pugi::xml_node object, const std::string& name) const;

    // The numbers of an attribute, separated by commas and/or blanks, each finite.
    std::vector<double> numbers(pugi::xml_node at, const char* attribute) const;
    double number(pugi::xml_node at, const char* attribute) const;

    // Caches, so that an object referenced twice becomes one material or texture.
    std::map<const void*, int> material_of_bsdf;  // bsdf element → Scene::materials index
    std::map<std::string, int> texture_of_file;   // "path|raw|filter|wrap" → Scene::textures

private:
    const XmlFiles& m_xml;
    Scene& m_scene;
    std::map<std::string, pugi::xml_node> m_ids;
};

// The colour an element gives (`rgb`, `srgb`, `spectrum`, `float`); fails on anything else.
Rgb color_value(const Context& ctx, pugi::xml_node element);

}  // namespace mvpl::scene::mitsuba
