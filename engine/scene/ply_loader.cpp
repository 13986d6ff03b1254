#include "engine/scene/ply_loader.h"

#include <bit>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <vector>

#include "engine/core/error.h"
#include "engine/core/regular_file.h"
#include "engine/scene/scene_loader.h"
#include "engine/scene/scene_range.h"

namespace mvpl::scene {

namespace {

// Bounds that keep a hostile header from asking for absurd allocations (as the glTF loader's).
constexpr uint64_t kMaxTriangles = uint64_t(1) << 28;
constexpr uint64_t kMaxPolygonVertices = uint64_t(1) << 16;

enum class Format { ascii, little_endian, big_endian };

enum class Type { i8, u8, i16, u16, i32, u32, f32, f64 };

struct Property {
    std::string name;
    Type type = Type::f32;
    bool is_list = false;
    Type count_type = Type::u8;
};

struct Element {
    std::string name;
    uint64_t count = 0;
    std::vector<Property> properties;
};

size_t type_size(Type t) {
    switch (t) {
        case Type::i8:
        case Type::u8:
            return 1;
        case Type::i16:
        case Type::u16:
            return 2;
        case Type::i32:
        case Type::u32:
        case Type::f32:
            return 4;
        case Type::f64:
            return 8;
    }
    return 1;
}

std::optional<Type> parse_type(const std::string& name) {
    if (name == "char" || name == "int8") return Type::i8;
    if (name == "uchar" || name == "uint8") return Type::u8;
    if (name == "short" || name == "int16") return Type::i16;
    if (name == "ushort" || name == "uint16") return Type::u16;
    if (name == "int" || name == "int32") return Type::i32;
    if (name == "uint" || name == "uint32") return Type::u32;
    if (name == "float" || name == "float32") return Type::f32;
    if (name == "double" || name == "float64") return Type::f64;
    return std::nullopt;
}

// Reads the values after the header, ascii or binary, one at a time.
class Reader {
public:
    Reader(const std::string& path, const std::string& data, size_t offset, Format format)
        : m_path(path), m_data(data), m_pos(offset), m_format(format) {}

    double read(Type type, const char* what) {
        return m_format == Format::ascii ? read_ascii(what) : read_binary(type, what);
    }
    size_t remaining() const { return m_data.size() - m_pos; }

private:
    [[noreturn]] void fail(const std::string& what) const { throw InputError(m_path, what); }

    double read_ascii(const char* what) {
        while (m_pos < m_data.size() && std::isspace(static_cast<unsigned char>(m_data[m_pos])))
            ++m_pos;
        if (m_pos == m_data.size()) fail(std::string("truncated ascii PLY: no value for ") + what);
        size_t end = m_pos;
        while (end < m_data.size() && !std::isspace(static_cast<unsigned char>(m_data[end])))
            ++end;
        const std::string token = m_data.substr(m_pos, std::min<size_t>(end - m_pos, 64));
        char* stop = nullptr;
        const double value = std::strtod(token.c_str(), &stop);
        if (end - m_pos > 64 || stop != token.c_str() + token.size())
            fail("bad number '" + token + "' for " + what + " in ascii PLY");
        m_pos = end;
        return value;
    }

    double read_binary(Type type, const char* what) {
        const size_t size = type_size(type);
        if (remaining() < size) fail(std::string("truncated binary PLY: data ends in ") + what);
        unsigned char b[8];
        std::memcpy(b, m_data.data() + m_pos, size);
        m_pos += size;
        const bool swap =
            (m_format == Format::big_endian) == (std::endian::native == std::endian::little);
        if (swap) {
            for (size_t i = 0; i < size / 2; ++i)
                std::swap(b[i], b[size - 1 - i]);
        }
        switch (type) {
            case Type::i8:
                return double(int8_t(b[0]));
            case Type::u8:
                return double(b[0]);
            case Type::i16:
                return double(load<int16_t>(b));
            case Type::u16:
                return double(load<uint16_t>(b));
            case Type::i32:
                return double(load<int32_t>(b));
            case Type::u32:
                return double(load<uint32_t>(b));
            case Type::f32:
                return double(load<float>(b));
            case Type::f64:
                return load<double>(b);
        }
        return 0.0;
    }

    template <typename T>
    static T load(const unsigned char* b) {
        T value;
        std::memcpy(&value, b, sizeof value);
        return value;
    }

    const std::string& m_path;
    const std::string& m_data;
    size_t m_pos;
    Format m_format;
};

struct Header {
    Format format = Format::ascii;
    std::vector<Element> elements;
    size_t data_offset = 0;
};

Header parse_header(const std::string& path, const std::string& data) {
    auto fail = [&path](const std::string& what) -> void {
        throw InputError(path, "bad PLY header: " + what);
    };
    if (data.empty()) throw InputError(path, "file is empty");
    Header h;
    size_t pos = 0;
    bool have_format = false, ended = false;
    for (int line_number = 1; !ended; ++line_number) {
        const size_t eol = data.find('\n', pos);
        if (eol == std::string::npos) fail("no end_header line");
        std::string line = data.substr(pos, eol - pos);
        if (!line.empty() && line.back() == '\r') line.pop_back();
        pos = eol + 1;
        std::istringstream in(line);
        std::string word;
        in >> word;
        if (line_number == 1) {
            if (line != "ply") fail("the file does not start with 'ply'");
            continue;
        }
        const std::string where = " (line " + std::to_string(line_number) + ")";
        if (word == "format") {
            std::string name, version;
            in >> name >> version;
            if (name == "ascii")
                h.format = Format::ascii;
            else if (name == "binary_little_endian")
                h.format = Format::little_endian;
            else if (name == "binary_big_endian")
                h.format = Format::big_endian;
            else
                fail("unknown format '" + name + "'" + where);
            if (version != "1.0") fail("unsupported version '" + version + "'" + where);
            have_format = true;
        } else if (word == "element") {
            Element e;
            std::string count;
            in >> e.name >> count;
            char* stop = nullptr;
            const unsigned long long n = std::strtoull(count.c_str(), &stop, 10);
            if (e.name.empty() || count.empty() || *stop != '\0' || count[0] == '-')
                fail("bad element line '" + line + "'" + where);
            e.count = n;
            h.elements.push_back(e);
        } else if (word == "property") {
            if (h.elements.empty()) fail("property before any element" + where);
            Property p;
            std::string type;
            in >> type;
            if (type == "list") {
                std::string count_type, item_type;
                in >> count_type >> item_type >> p.name;
                const auto ct = parse_type(count_type), it = parse_type(item_type);
                if (!ct || !it || p.name.empty()) fail("bad list property '" + line + "'" + where);
                if (*ct == Type::f32 || *ct == Type::f64) fail("float list count" + where);
                p.is_list = true;
                p.count_type = *ct;
                p.type = *it;
            } else {
                in >> p.name;
                const auto t = parse_type(type);
                if (!t || p.name.empty()) fail("bad property '" + line + "'" + where);
                p.type = *t;
            }
            h.elements.back().properties.push_back(p);
        } else if (word == "end_header") {
            ended = true;
        } else if (word != "comment" && word != "obj_info" && !word.empty()) {
            fail("unknown keyword '" + word + "'" + where);
        }
    }
    if (!have_format) fail("no format line");
    h.data_offset = pos;
    return h;
}

int property_index(const Element& e, const char* name) {
    for (size_t i = 0; i < e.properties.size(); ++i) {
        if (e.properties[i].name == name && !e.properties[i].is_list) return int(i);
    }
    return -1;
}

// Every value takes at least one byte (binary) or two characters (ascii, with its separator): a
// count the rest of the file cannot hold is refused before allocating.
void check_element_fits(const std::string& path, const Element& e, Format format,
                        size_t remaining) {
    size_t min_bytes = 0;
    for (const Property& p : e.properties)
        min_bytes += p.is_list ? type_size(p.count_type) : type_size(p.type);
    if (format == Format::ascii) min_bytes = 2 * e.properties.size();
    if (min_bytes > 0 && e.count > remaining / min_bytes) {
        throw InputError(path, "truncated PLY: element '" + e.name + "' declares " +
                                   std::to_string(e.count) + " entries, more than the " +
                                   std::to_string(remaining) + " bytes after the header hold");
    }
}

// The properties of the vertex element that make a mesh vertex (-1: absent).
struct VertexColumns {
    int xyz[3] = {-1, -1, -1};
    int nxyz[3] = {-1, -1, -1};
    int uv[2] = {-1, -1};
    bool normals = false;  // nx, ny and nz all present
};

VertexColumns vertex_columns(const std::string& path, const Element& e) {
    VertexColumns c;
    const char* names[6] = {"x", "y", "z", "nx", "ny", "nz"};
    for (int i = 0; i < 3; ++i) {
        c.xyz[i] = property_index(e, names[i]);
        c.nxyz[i] = property_index(e, names[3 + i]);
    }
    if (c.xyz[0] < 0 || c.xyz[1] < 0 || c.xyz[2] < 0)
        throw InputError(path, "the vertex element has no x, y and z properties");
    c.normals = c.nxyz[0] >= 0 && c.nxyz[1] >= 0 && c.nxyz[2] >= 0;
    // Texture coordinates under the names Mitsuba's PLY reader accepts.
    const char* uv_names[4][2] = {
        {"u", "v"}, {"s", "t"}, {"texture_u", "texture_v"}, {"texture_s", "texture_t"}};
    for (const auto& pair : uv_names) {
        if (c.uv[0] >= 0) break;
        c.uv[0] = property_index(e, pair[0]);
        c.uv[1] = property_index(e, pair[1]);
        if (c.uv[1] < 0) c.uv[0] = -1;
    }
    return c;
}

// The face element's vertex index list.
int face_list_column(const std::string& path, const Element& e) {
    int list = -1;
    for (size_t i = 0; i < e.properties.size(); ++i) {
        const Property& p = e.properties[i];
        if (p.is_list && (p.name == "vertex_indices" || p.name == "vertex_index")) list = int(i);
    }
    if (list < 0) throw InputError(path, "the face element has no vertex_indices list");
    return list;
}

// Entry n of element e: its scalar properties into `values`, the items of property `list` into
// `polygon` (checked as indices of `vertex_count` vertices); other lists are read and dropped.
void read_entry(Reader& reader, const std::string& path, const Element& e, uint64_t n, int list,
                size_t vertex_count, std::vector<double>& values, std::vector<uint32_t>& polygon) {
    for (size_t i = 0; i < e.properties.size(); ++i) {
        const Property& p = e.properties[i];
        if (!p.is_list) {
            values[i] = reader.read(p.type, p.name.c_str());
            continue;
        }
        const double count = reader.read(p.count_type, p.name.c_str());
        if (!(count >= 0.0 && count <= double(kMaxPolygonVertices)) || count != std::floor(count)) {
            throw InputError(path, "bad list length " + std::to_string(count) + " in " + e.name +
                                       " " + std::to_string(n));
        }
        if (int(i) == list) polygon.clear();
        for (uint64_t k = 0; k < uint64_t(count); ++k) {
            const double v = reader.read(p.type, p.name.c_str());
            if (int(i) != list) continue;
            if (!(v >= 0.0 && v < double(vertex_count)) || v != std::floor(v)) {
                throw InputError(path, "face " + std::to_string(n) + " refers to vertex " +
                                           std::to_string(int64_t(v)) + " of " +
                                           std::to_string(vertex_count));
            }
            polygon.push_back(uint32_t(v));
        }
    }
}

// Vertex n of the mesh from its element's `values`, checked finite and within range.
void store_vertex(const std::string& path, uint64_t n, const std::vector<double>& values,
                  const VertexColumns& c, Mesh& mesh) {
    const Vec3 p = Vec3(float(values[size_t(c.xyz[0])]), float(values[size_t(c.xyz[1])]),
                        float(values[size_t(c.xyz[2])]));
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
        throw InputError(path, "vertex " + std::to_string(n) +
                                   " has a non-finite position (NaN, infinity or "
                                   "beyond float range)");
    }
    for (int i = 0; i < 3; ++i) {
        // scene_range.h: what Embree and the shaders can carry.
        const double x = values[size_t(c.xyz[i])];
        if (std::abs(x) > kMaxCoordinate) {
            throw InputError(path, "vertex " + std::to_string(n) + " has " +
                                       std::string(1, "xyz"[i]) + " = " + number_text(x) +
                                       ", beyond the supported magnitude " +
                                       number_text(kMaxCoordinate));
        }
    }
    mesh.positions[n] = p;
    if (c.uv[0] >= 0) {
        mesh.uv0[n] = Vec2(float(values[size_t(c.uv[0])]), float(values[size_t(c.uv[1])]));
        if (!std::isfinite(mesh.uv0[n].x) || !std::isfinite(mesh.uv0[n].y))
            throw InputError(path,
                             "vertex " + std::to_string(n) + " has non-finite texture coordinates");
    }
    if (c.normals) {
        mesh.normals[n] = Vec3(float(values[size_t(c.nxyz[0])]), float(values[size_t(c.nxyz[1])]),
                               float(values[size_t(c.nxyz[2])]));
    }
}

// Face n (`polygon`, vertex indices) as triangles.
void add_face(const std::string& path, uint64_t n, const std::vector<uint32_t>& polygon,
              Mesh& mesh) {
    if (polygon.size() < 3) {
        throw InputError(path, "face " + std::to_string(n) + " has " +
                                   std::to_string(polygon.size()) +
                                   " vertices; a face needs at least 3");
    }
    // Fan triangulation: (0, k, k+1), which keeps the polygon's winding.
    for (size_t k = 1; k + 1 < polygon.size(); ++k)
        mesh.indices.insert(mesh.indices.end(), {polygon[0], uint32_t(polygon[k]), polygon[k + 1]});
    if (mesh.indices.size() / 3 > kMaxTriangles) throw InputError(path, "more than 2^28 triangles");
}

}  // namespace

Mesh read_ply_mesh(const std::string& path) {
    require_regular_file(path);
    std::ifstream file(path, std::ios::binary);
    if (!file) throw InputError(path, "cannot open the file");
    const std::string data((std::istreambuf_iterator<char>(file)),
                           std::istreambuf_iterator<char>());
    const Header header = parse_header(path, data);
    Reader reader(path, data, header.data_offset, header.format);

    Mesh mesh;
    mesh.name = std::filesystem::path(path).stem().string();
    bool have_vertices = false, have_faces = false;
    for (const Element& e : header.elements) {
        check_element_fits(path, e, header.format, reader.remaining());
        const bool is_vertex = e.name == "vertex" && !have_vertices;
        const bool is_face = e.name == "face" && !have_faces;
        VertexColumns columns;
        int list = -1;
        if (is_vertex) {
            columns = vertex_columns(path, e);
            mesh.positions.resize(e.count);
            if (columns.normals) mesh.normals.resize(e.count);
            if (columns.uv[0] >= 0) mesh.uv0.resize(e.count);
        }
        if (is_face) list = face_list_column(path, e);
        std::vector<double> values(e.properties.size());
        std::vector<uint32_t> polygon;
        for (uint64_t n = 0; n < e.count; ++n) {
            read_entry(reader, path, e, n, list, mesh.positions.size(), values, polygon);
            if (is_vertex) store_vertex(path, n, values, columns, mesh);
            if (is_face) add_face(path, n, polygon, mesh);
        }
        have_vertices = have_vertices || is_vertex;
        have_faces = have_faces || is_face;
    }
    if (!have_vertices) throw InputError(path, "no vertex element");
    if (mesh.indices.empty()) throw InputError(path, "no faces: a point cloud has no triangles");
    return mesh;
}

Scene load_ply(const std::string& path) {
    Mesh mesh = read_ply_mesh(path);
    mesh.uv0.clear();  // a bare mesh gets an untextured material
    std::vector<Mesh> meshes;
    meshes.push_back(std::move(mesh));
    return mesh_scene(path, std::move(meshes), {default_mesh_material()});
}

}  // namespace mvpl::scene
