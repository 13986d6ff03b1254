#pragma once
// The XML side of a Mitsuba scene: the file and the files it includes, parsed with pugixml, with
// what Mitsuba's parser does before any plugin sees a property — `<default>` and `-D` parameters
// substituted for `$name` in every attribute, `<include>` spliced in, `<path>` and `-a` folders
// added to the file resolver, and Mitsuba 0.x's camelCase property names upgraded to 3.x's
// snake_case (Mitsuba 3's own upgrade: toWorld → to_world, intIOR → int_ior). Every message
// names FILE:LINE of the element at fault.
#include <pugixml.hpp>

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "engine/scene/scene_loader.h"

namespace mvpl::scene::mitsuba {

class XmlFiles {
public:
    // Reads `path` and its includes; throws InputError (FILE:LINE: what) on malformed XML, a
    // root that is not <scene>, a missing include or an include cycle, and past the bounds on
    // element nesting, files and bytes loaded, and substituted length. A $parameter without a
    // value stays in the text (Context::numbers names it when it is read).
    XmlFiles(const std::string& path, const LoadOptions& options);
    ~XmlFiles();
    XmlFiles(const XmlFiles&) = delete;
    XmlFiles& operator=(const XmlFiles&) = delete;

    pugi::xml_node root() const;
    const std::string& path() const;
    // The element children of `node` with every <include> replaced by the included scene's
    // children and <default>/<path> left out.
    std::vector<pugi::xml_node> children(pugi::xml_node node) const;

    // "FILE:LINE" of an element (of whichever file it came from).
    std::string where(pugi::xml_node node) const;
    [[noreturn]] void fail(pugi::xml_node node, const std::string& what) const;
    // `filename` as Mitsuba's file resolver finds it: absolute, or relative to the folder of the
    // file that names it, the main file's folder, then the `<path>` and -a folders in order.
    // Fails at `node` when no such regular file exists.
    std::string resolve(pugi::xml_node node, const std::string& filename) const;

private:
    struct Source;
    size_t load(const std::string& path, pugi::xml_node from, int depth);
    void preprocess(size_t source, pugi::xml_node node, bool upgrade, int depth, int nesting);
    // `text` with each $name replaced by its value; fails at `node` past the length bounds.
    std::string substitute(pugi::xml_node node, const std::string& text);
    const Source& source_of(pugi::xml_node node) const;

    std::vector<std::unique_ptr<Source>> m_sources;
    std::map<const void*, size_t> m_includes;  // <include> element → its source
    std::map<std::string, std::string> m_parameters;
    std::vector<std::filesystem::path> m_search_paths;
    uintmax_t m_bytes_read = 0;
    size_t m_substituted_bytes = 0;
};

}  // namespace mvpl::scene::mitsuba
