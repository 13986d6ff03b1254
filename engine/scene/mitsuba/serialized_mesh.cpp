#include "engine/scene/mitsuba/serialized_mesh.h"

#include <zlib.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "engine/core/error.h"
#include "engine/core/regular_file.h"
#include "engine/scene/mesh_limits.h"
#include "engine/scene/scene_range.h"

namespace mvpl::scene::mitsuba {

namespace {

constexpr uint16_t kMagic = 0x041C;
constexpr uint32_t kHasNormals = 0x0001, kHasUvs = 0x0002, kHasColors = 0x0008,
                   kFaceNormals = 0x0010, kSingle = 0x1000, kDouble = 0x2000;
constexpr uint64_t kMaxInflated = uint64_t(1) << 32;

template <class T>
T read_le(const std::string& data, size_t offset) {
    T v{};
    std::memcpy(&v, data.data() + offset, sizeof(T));  // the format and x86 are little-endian
    return v;
}

// The zlib stream from `offset` to its end, refusing more than `limit` bytes.
std::string inflate_stream(const std::string& path, const std::string& data, size_t offset,
                           uint64_t limit) {
    z_stream z{};
    if (inflateInit(&z) != Z_OK) throw InputError(path, "zlib initialisation failed");
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data() + offset));
    z.avail_in = uInt(std::min<size_t>(data.size() - offset, size_t(UINT32_MAX)));
    std::string out;
    int status = Z_OK;
    while (status == Z_OK) {
        const size_t old = out.size();
        if (old >= limit) {
            inflateEnd(&z);
            throw InputError(path, "a shape decompresses to more than its counts allow");
        }
        out.resize(old + (size_t(1) << 20));
        z.next_out = reinterpret_cast<Bytef*>(out.data() + old);
        z.avail_out = uInt(size_t(1) << 20);
        status = inflate(&z, Z_NO_FLUSH);
        out.resize(out.size() - z.avail_out);
        if (status == Z_BUF_ERROR && z.avail_in == 0) break;
    }
    inflateEnd(&z);
    if (status != Z_STREAM_END)
        throw InputError(path, "corrupt or truncated zlib data" +
                                   (z.msg ? std::string(" (") + z.msg + ")" : std::string()));
    return out;
}

// One shape's stream, inflated, and the file's format version.
struct ShapeData {
    std::string bytes;
    uint16_t version = 0;
};

// Shape `shape_index` of the file's `data`, found through the table at the file's end.
ShapeData shape_data(const std::string& path, const std::string& data, int shape_index) {
    if (data.size() < 8 || read_le<uint16_t>(data, 0) != kMagic)
        throw InputError(path, "not a Mitsuba serialized mesh (bad header)");
    const uint16_t version = read_le<uint16_t>(data, 2);
    if (version != 3 && version != 4)
        throw InputError(
            path, "serialized format version " + std::to_string(version) + " (expected 3 or 4)");
    const uint32_t count = read_le<uint32_t>(data, data.size() - 4);
    const size_t entry = version == 4 ? 8 : 4;
    if (shape_index < 0 || uint64_t(shape_index) >= count ||
        uint64_t(count) * entry + 4 > data.size())
        throw InputError(path, "shape_index " + std::to_string(shape_index) +
                                   " is beyond the file's " + std::to_string(count) + " shapes");
    const size_t table = data.size() - 4 - size_t(count) * entry;
    const uint64_t offset = version == 4 ? read_le<uint64_t>(data, table + size_t(shape_index) * 8)
                                         : read_le<uint32_t>(data, table + size_t(shape_index) * 4);
    if (offset + 4 >= table || read_le<uint16_t>(data, size_t(offset)) != kMagic)
        throw InputError(path, "shape " + std::to_string(shape_index) + " has a bad offset");
    const uint64_t limit = std::min<uint64_t>(kMaxInflated, (table - offset) * 1100 + 4096);
    return {inflate_stream(path, data, size_t(offset) + 4, limit), version};
}

// A shape's stream read front to back, every read checked against its end.
struct ShapeReader {
    const std::string& path;
    int shape_index;
    const std::string& s;
    size_t at = 0;

    void need(uint64_t bytes) const {
        if (bytes > s.size() || at > s.size() - bytes)
            throw InputError(path, "shape " + std::to_string(shape_index) + " is truncated");
    }
    // n reals (doubles or floats in the stream) as floats, each finite and within range.
    std::vector<float> read_reals(size_t n, bool doubles) {
        const size_t real = doubles ? 8 : 4;
        need(uint64_t(n) * real);
        std::vector<float> out(n);
        for (size_t i = 0; i < n; ++i) {
            const double v =
                doubles ? read_le<double>(s, at + i * 8) : double(read_le<float>(s, at + i * 4));
            if (!std::isfinite(v) || std::abs(v) > kMaxCoordinate)
                throw InputError(path, "shape " + std::to_string(shape_index) +
                                           " has a non-finite or out-of-range value");
            out[i] = float(v);
        }
        at += n * real;
        return out;
    }
};

// The per-vertex arrays that `flags` announce, in the stream's order.
void read_vertex_data(ShapeReader& r, uint32_t flags, bool doubles, uint64_t vertices, Mesh& mesh) {
    const std::vector<float> p = r.read_reals(size_t(vertices) * 3, doubles);
    for (size_t i = 0; i < vertices; ++i)
        mesh.positions.emplace_back(p[3 * i], p[3 * i + 1], p[3 * i + 2]);
    if (flags & kHasNormals) {
        const std::vector<float> n = r.read_reals(size_t(vertices) * 3, doubles);
        for (size_t i = 0; i < vertices; ++i)
            mesh.normals.emplace_back(n[3 * i], n[3 * i + 1], n[3 * i + 2]);
    }
    if (flags & kHasUvs) {
        const std::vector<float> uv = r.read_reals(size_t(vertices) * 2, doubles);
        for (size_t i = 0; i < vertices; ++i)
            mesh.uv0.emplace_back(uv[2 * i], uv[2 * i + 1]);
    }
    if (flags & kHasColors)
        r.read_reals(size_t(vertices) * 3, doubles);  // not used by any BSDF we map
}

// The triangles' vertex indices, 64-bit where the vertex count needs them.
void read_indices(ShapeReader& r, uint64_t vertices, uint64_t triangles, Mesh& mesh) {
    const bool wide = vertices > uint64_t(UINT32_MAX);
    r.need(triangles * 3 * (wide ? 8 : 4));
    mesh.indices.resize(size_t(triangles) * 3);
    for (size_t i = 0; i < mesh.indices.size(); ++i) {
        const uint64_t index =
            wide ? read_le<uint64_t>(r.s, r.at + i * 8) : read_le<uint32_t>(r.s, r.at + i * 4);
        if (index >= vertices)
            throw InputError(r.path, "shape " + std::to_string(r.shape_index) + ": index " +
                                         std::to_string(index) + " is out of range");
        mesh.indices[i] = uint32_t(index);
    }
}

}  // namespace

Mesh read_serialized_mesh(const std::string& path, int shape_index, bool* face_normals) {
    require_regular_file(path);
    std::ifstream file(path, std::ios::binary);
    if (!file) throw InputError(path, "cannot open the file");
    const std::string data((std::istreambuf_iterator<char>(file)),
                           std::istreambuf_iterator<char>());
    const ShapeData shape = shape_data(path, data, shape_index);
    const std::string& s = shape.bytes;
    ShapeReader r{path, shape_index, s};
    r.need(4);
    const uint32_t flags = read_le<uint32_t>(s, r.at);
    r.at += 4;
    Mesh mesh;
    if (shape.version == 4) {
        const size_t end = s.find('\0', r.at);
        if (end == std::string::npos) throw InputError(path, "unterminated shape name");
        mesh.name = s.substr(r.at, end - r.at);
        r.at = end + 1;
    }
    if (mesh.name.empty()) mesh.name = std::filesystem::path(path).stem().string();
    r.need(16);
    const uint64_t vertices = read_le<uint64_t>(s, r.at);
    const uint64_t triangles = read_le<uint64_t>(s, r.at + 8);
    r.at += 16;
    if (vertices > kMaxMeshVertices || triangles > kMaxMeshTriangles || vertices == 0 ||
        triangles == 0)
        throw InputError(path, "shape " + std::to_string(shape_index) + " has " +
                                   std::to_string(vertices) + " vertices and " +
                                   std::to_string(triangles) + " triangles");
    const bool doubles = (flags & kDouble) != 0;
    if (doubles == ((flags & kSingle) != 0))
        throw InputError(path, "the flags name neither single nor double precision");
    read_vertex_data(r, flags, doubles, vertices, mesh);
    read_indices(r, vertices, triangles, mesh);
    if (face_normals) *face_normals = (flags & kFaceNormals) != 0;
    return mesh;
}

}  // namespace mvpl::scene::mitsuba
