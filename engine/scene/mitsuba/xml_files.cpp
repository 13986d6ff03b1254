#include "engine/scene/mitsuba/xml_files.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <iterator>

#include "engine/core/error.h"
#include "engine/core/regular_file.h"

namespace mvpl::scene::mitsuba {

namespace fs = std::filesystem;

namespace {

// Includes nest no deeper than this: deeper is a cycle in practice, and it bounds the recursion.
constexpr int kMaxIncludeDepth = 16;
// Elements nest no deeper than this in one file: real scenes nest under 10 levels, and the
// recursion of preprocess() over 256 levels (times kMaxIncludeDepth files) stays far from the
// stack's end even under AddressSanitizer, where 20 000 levels overflowed it.
constexpr int kMaxElementDepth = 256;
// Bytes of XML read in all (the main file and every include, counted each time it is spliced):
// scenes of the Mitsuba galleries are under a few MiB; this bounds memory against a fan-out of
// includes (each file including the next several times).
constexpr uintmax_t kMaxXmlBytes = uintmax_t(1) << 28;
// Files loaded in all, each include counted each time: galleries' scenes include a handful; a
// fan-out of 16 files each including the next three times would otherwise load 3^15 of them.
constexpr size_t kMaxIncludes = 1024;
// One attribute after $parameter substitution, and all substituted text together: the longest
// real values (spectra, matrices) are a few KiB; a <default> pasting the previous one 16 times
// grows 16-fold a level and would otherwise exhaust memory.
constexpr size_t kMaxValueLength = size_t(1) << 20;
constexpr size_t kMaxSubstitutedBytes = size_t(1) << 28;
// An error quotes at most this many characters of an attribute's value.
constexpr size_t kQuotedPrefix = 40;

// Mitsuba 3's upgrade of a 0.x property name: a capital starts a new word unless it continues
// an acronym (intIOR → int_ior, toWorld → to_world, alphaU → alpha_u).
std::string snake_case(const std::string& name) {
    std::string out;
    for (size_t i = 0; i < name.size(); ++i) {
        const unsigned char c = static_cast<unsigned char>(name[i]);
        if (std::isupper(c) && i > 0 && !std::isupper(static_cast<unsigned char>(name[i - 1])))
            out += '_';
        out += char(std::tolower(c));
    }
    return out;
}

bool is_parameter_char(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

}  // namespace

struct XmlFiles::Source {
    std::string path;
    std::string text;
    pugi::xml_document doc;
    std::vector<size_t> line_starts;  // offset of each line's first character

    int line(ptrdiff_t offset) const {
        if (offset < 0) return 0;
        return int(std::upper_bound(line_starts.begin(), line_starts.end(), size_t(offset)) -
                   line_starts.begin());
    }
};

XmlFiles::XmlFiles(const std::string& path, const LoadOptions& options) {
    for (const auto& [name, value] : options.defines)
        m_parameters[name] = value;
    for (const std::string& folder : options.search_paths)
        m_search_paths.emplace_back(folder);
    load(path, pugi::xml_node(), 0);
}

XmlFiles::~XmlFiles() = default;

pugi::xml_node XmlFiles::root() const {
    return m_sources.front()->doc.document_element();
}

const std::string& XmlFiles::path() const {
    return m_sources.front()->path;
}

size_t XmlFiles::load(const std::string& path, pugi::xml_node from, int depth) {
    const auto refuse = [&](const std::string& what) {
        if (from) fail(from, what);
        throw InputError(path, what);
    };
    if (depth > kMaxIncludeDepth)
        refuse("includes nest deeper than " + std::to_string(kMaxIncludeDepth) + " (a cycle?)");
    if (!from) require_regular_file(path);  // includes are checked where resolved
    std::error_code error;
    const uintmax_t size = fs::file_size(path, error);
    if (error) refuse("cannot read '" + path + "'");
    if (m_sources.size() >= kMaxIncludes)
        refuse("more than " + std::to_string(kMaxIncludes) +
               " files loaded in all (includes fan out)");
    if (size > kMaxXmlBytes - m_bytes_read)
        refuse("'" + path + "' takes the XML read in all past " +
               std::to_string(kMaxXmlBytes >> 20) + " MiB (includes fan out?)");
    m_bytes_read += size;
    std::ifstream file(path, std::ios::binary);
    if (!file) refuse("cannot open '" + path + "'");
    auto source = std::make_unique<Source>();
    source->path = path;
    source->text.assign(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
    source->line_starts.push_back(0);
    for (size_t i = 0; i < source->text.size(); ++i) {
        if (source->text[i] == '\n') source->line_starts.push_back(i + 1);
    }
    const pugi::xml_parse_result parsed =
        source->doc.load_buffer(source->text.data(), source->text.size(),
                                pugi::parse_default | pugi::parse_ws_pcdata_single);
    if (!parsed) {
        throw InputError(path + ":" + std::to_string(source->line(parsed.offset)),
                         std::string("malformed XML: ") + parsed.description());
    }
    const size_t index = m_sources.size();
    m_sources.push_back(std::move(source));
    const pugi::xml_node scene = m_sources.back()->doc.document_element();
    if (std::string(scene.name()) != "scene")
        fail(scene, "the root element is <" + std::string(scene.name()) + ">, not <scene>");
    // Mitsuba 0.x files carry version="0.x.y"; 2.0 introduced the snake_case names.
    const std::string version = scene.attribute("version").as_string("3.0.0");
    preprocess(index, scene, !version.empty() && (version[0] == '0' || version[0] == '1'), depth,
               0);
    return index;
}

const XmlFiles::Source& XmlFiles::source_of(pugi::xml_node node) const {
    const pugi::xml_node document = node.root();
    for (const auto& s : m_sources) {
        if (s->doc == document) return *s;
    }
    return *m_sources.front();
}

std::string XmlFiles::where(pugi::xml_node node) const {
    const Source& s = source_of(node);
    return s.path + ":" + std::to_string(s.line(node.offset_debug()));
}

void XmlFiles::fail(pugi::xml_node node, const std::string& what) const {
    throw InputError(where(node), what);
}

std::string XmlFiles::substitute(pugi::xml_node node, const std::string& text) {
    const auto too_long = [&](const std::string& limit) {
        const std::string prefix = text.substr(0, kQuotedPrefix);
        fail(node, "the value '" + prefix + (text.size() > prefix.size() ? "..." : "") +
                       "' expands past " + limit + " (nested $parameters)");
    };
    std::string out;
    for (size_t i = 0; i < text.size(); ++i) {
        if (out.size() > kMaxValueLength) too_long(std::to_string(kMaxValueLength >> 20) + " MiB");
        if (text[i] != '$') {
            out += text[i];
            continue;
        }
        size_t end = i + 1;
        while (end < text.size() && is_parameter_char(text[end]))
            ++end;
        const std::string name = text.substr(i + 1, end - i - 1);
        const auto found = m_parameters.find(name);
        // As in Mitsuba, an undefined parameter fails only where its value is read
        // (Context::numbers says which), so a dropped plugin's $spp does no harm.
        out += found == m_parameters.end() ? "$" + name : found->second;
        i = end - 1;
    }
    if (out.size() > kMaxValueLength) too_long(std::to_string(kMaxValueLength >> 20) + " MiB");
    m_substituted_bytes += out.size();
    if (m_substituted_bytes > kMaxSubstitutedBytes)
        too_long(std::to_string(kMaxSubstitutedBytes >> 20) + " MiB in all");
    return out;
}

void XmlFiles::preprocess(size_t source, pugi::xml_node node, bool upgrade, int depth,
                          int nesting) {
    for (pugi::xml_node child = node.first_child(); child; child = child.next_sibling()) {
        if (child.type() != pugi::node_element) continue;
        if (nesting >= kMaxElementDepth)
            fail(child, "elements nest deeper than " + std::to_string(kMaxElementDepth));
        for (pugi::xml_attribute a = child.first_attribute(); a; a = a.next_attribute()) {
            const std::string value = a.value();
            if (value.find('$') != std::string::npos) a.set_value(substitute(child, value).c_str());
        }
        const std::string tag = child.name();
        if (upgrade) {
            if (pugi::xml_attribute name = child.attribute("name"))
                name.set_value(snake_case(name.value()).c_str());
        }
        if (tag == "default") {
            const std::string name = child.attribute("name").as_string();
            if (name.empty()) fail(child, "<default> without a name");
            if (!child.attribute("value"))
                fail(child, "<default name=\"" + name + "\"> without a value");
            m_parameters.emplace(name, child.attribute("value").as_string());
        } else if (tag == "path") {
            const fs::path folder = child.attribute("value").as_string();
            m_search_paths.push_back(
                folder.is_absolute() ? folder
                                     : fs::path(m_sources[source]->path).parent_path() / folder);
        } else if (tag == "include") {
            const std::string file = resolve(child, child.attribute("filename").as_string());
            m_includes[child.internal_object()] = load(file, child, depth + 1);
        } else {
            preprocess(source, child, upgrade, depth, nesting + 1);
        }
    }
}

std::vector<pugi::xml_node> XmlFiles::children(pugi::xml_node node) const {
    std::vector<pugi::xml_node> out;
    for (pugi::xml_node child = node.first_child(); child; child = child.next_sibling()) {
        if (child.type() != pugi::node_element) continue;
        const std::string tag = child.name();
        if (tag == "default" || tag == "path") continue;
        if (tag == "include") {
            const auto found = m_includes.find(child.internal_object());
            if (found == m_includes.end()) continue;
            const std::vector<pugi::xml_node> inner =
                children(m_sources[found->second]->doc.document_element());
            out.insert(out.end(), inner.begin(), inner.end());
            continue;
        }
        out.push_back(child);
    }
    return out;
}

std::string XmlFiles::resolve(pugi::xml_node node, const std::string& filename) const {
    if (filename.empty()) fail(node, "<" + std::string(node.name()) + "> names no file");
    const fs::path name(filename);
    std::vector<fs::path> candidates;
    if (name.is_absolute()) {
        candidates.push_back(name);
    } else {
        candidates.push_back(fs::path(source_of(node).path).parent_path() / name);
        candidates.push_back(fs::path(path()).parent_path() / name);
        for (const fs::path& folder : m_search_paths)
            candidates.push_back(folder / name);
    }
    for (const fs::path& c : candidates) {
        std::error_code error;
        if (!fs::is_regular_file(c, error)) continue;
        // Kernel pseudo-files pass as regular files but may never end (/proc/kcore).
        const std::string real = fs::weakly_canonical(c, error).string();
        if (real.starts_with("/proc/") || real.starts_with("/sys/"))
            fail(node, "'" + filename + "' is not a regular file");
        return c.lexically_normal().string();
    }
    fail(node, "file '" + filename + "' not found (searched the scene's folder" +
                   (m_search_paths.empty() ? std::string() : " and the -a/<path> folders") + ")");
}

}  // namespace mvpl::scene::mitsuba
