#include "engine/scene/mitsuba/obj_mesh.h"

#include <array>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "engine/core/error.h"
#include "engine/core/regular_file.h"
#include "engine/scene/mesh_limits.h"
#include "engine/scene/scene_range.h"

namespace mvpl::scene::mitsuba {

namespace {

class LineReader {
public:
    LineReader(const std::string& path, int line, const std::string& text)
        : m_path(path), m_line(line), m_text(text) {}

    [[noreturn]] void fail(const std::string& what) const {
        throw InputError(m_path + ":" + std::to_string(m_line), what);
    }
    bool next(std::string& token) {
        while (m_pos < m_text.size() && (m_text[m_pos] == ' ' || m_text[m_pos] == '\t'))
            ++m_pos;
        if (m_pos >= m_text.size()) return false;
        const size_t start = m_pos;
        while (m_pos < m_text.size() && m_text[m_pos] != ' ' && m_text[m_pos] != '\t')
            ++m_pos;
        token = m_text.substr(start, m_pos - start);
        return true;
    }
    float number() {
        std::string token;
        if (!next(token)) fail("missing number");
        float v = 0.0f;
        const auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), v);
        if (ec != std::errc() || ptr != token.data() + token.size() || !std::isfinite(v))
            fail("'" + token + "' is not a finite number");
        return v;
    }
    // Three numbers in the order written (a constructor's arguments have no order).
    Vec3 triple() {
        const float x = number();
        const float y = number();
        return Vec3(x, y, number());
    }

private:
    std::string m_path;
    int m_line;
    std::string m_text;
    size_t m_pos = 0;
};

// A 1-based (or negative, relative) OBJ index into a list of `count`; 0 when absent.
long resolve_index(LineReader& r, const std::string& text, size_t count) {
    if (text.empty()) return 0;
    long v = 0;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || ptr != text.data() + text.size()) r.fail("bad index '" + text + "'");
    if (v < 0) v += long(count) + 1;
    if (v < 1 || size_t(v) > count) r.fail("index " + text + " is out of range");
    return v;
}

}  // namespace

Mesh read_obj_mesh(const std::string& path, bool flip_tex_coords) {
    require_regular_file(path);
    std::ifstream file(path, std::ios::binary);
    if (!file) throw InputError(path, "cannot open the file");
    Mesh mesh;
    mesh.name = std::filesystem::path(path).stem().string();
    std::vector<Vec3> v, vn;
    std::vector<Vec2> vt;
    std::map<std::array<long, 3>, uint32_t> shared;
    std::vector<std::array<long, 3>> keys;
    std::string line;
    int number = 0;
    while (std::getline(file, line)) {
        ++number;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        LineReader r(path, number, line);
        std::string tag;
        if (!r.next(tag) || tag[0] == '#') continue;
        if (tag == "v") {
            const Vec3 p = r.triple();
            for (int c = 0; c < 3; ++c) {
                if (std::abs(double(p[c])) > kMaxCoordinate)
                    r.fail("vertex coordinate beyond " + number_text(kMaxCoordinate));
            }
            v.push_back(p);
        } else if (tag == "vn") {
            vn.push_back(r.triple());
        } else if (tag == "vt") {
            Vec2 uv(r.number(), 0.0f);
            uv.y = r.number();
            if (flip_tex_coords) uv.y = 1.0f - uv.y;
            vt.push_back(uv);
        } else if (tag == "f") {
            std::vector<uint32_t> polygon;
            std::string token;
            while (r.next(token)) {
                std::array<std::string, 3> parts;
                size_t part = 0;
                for (char c : token) {
                    if (c == '/') {
                        if (++part > 2) r.fail("bad face vertex '" + token + "'");
                    } else {
                        parts[part] += c;
                    }
                }
                const std::array<long, 3> key = {resolve_index(r, parts[0], v.size()),
                                                 resolve_index(r, parts[1], vt.size()),
                                                 resolve_index(r, parts[2], vn.size())};
                if (key[0] == 0) r.fail("face vertex '" + token + "' has no position");
                const auto [it, inserted] = shared.emplace(key, uint32_t(keys.size()));
                if (inserted) keys.push_back(key);
                polygon.push_back(it->second);
            }
            if (polygon.size() < 3) r.fail("a face needs at least 3 vertices");
            for (size_t k = 1; k + 1 < polygon.size(); ++k)
                mesh.indices.insert(mesh.indices.end(), {polygon[0], polygon[k], polygon[k + 1]});
            if (mesh.indices.size() / 3 > kMaxMeshTriangles) r.fail("more than 2^28 triangles");
        }
    }
    if (mesh.indices.empty()) throw InputError(path, "no faces");
    bool all_uv = true, all_normals = true;
    for (const auto& key : keys) {
        all_uv = all_uv && key[1] != 0;
        all_normals = all_normals && key[2] != 0;
    }
    for (const auto& key : keys) {
        mesh.positions.push_back(v[size_t(key[0] - 1)]);
        if (all_uv) mesh.uv0.push_back(vt[size_t(key[1] - 1)]);
        if (all_normals) mesh.normals.push_back(vn[size_t(key[2] - 1)]);
    }
    return mesh;
}

}  // namespace mvpl::scene::mitsuba
