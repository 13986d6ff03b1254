#include "engine/scene/mitsuba/serialized_mesh.h"

#include <zlib.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "engine/core/error.h"
#include "engine/core/regular_file.h"
#include "engine/scene/scene_range.h"

namespace mvpl::scene::mitsuba {

namespace {

constexpr uint16_t kMagic = 0x041C;
constexpr uint32_t kHasNormals = 0x0001, kHasUvs = 0x0002, kHasColors = 0x0008,
                   kFaceNormals = 0x0010, kSingle = 0x1000, kDouble = 0x2000;
constexpr uint64_t kMaxVertices = uint64_t(1) << 28, kMaxTriangles = uint64_t(1) << 28;
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

}  // namespace

Mesh read_serialized_mesh(const std::string& path, int shape_index, bool* face_normals) {
    require_regular_file(path);
    std::ifstream file(path, std::ios::binary);
    if (!file) throw InputError(path, "cannot open the file");
    const std::string data((std::istreambuf_iterator<char>(file)),
                           std::istreambuf_iterator<char>());
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
    const std::string s = inflate_stream(path, data, size_t(offset) + 4, limit);

    size_t at = 0;
    const auto need = [&](uint64_t bytes) {
        if (bytes > s.size() || at > s.size() - bytes)
            throw InputError(path, "shape " + std::to_string(shape_index) + " is truncated");
    };
    need(4);
    const uint32_t flags = read_le<uint32_t>(s, at);
    at += 4;
    Mesh mesh;
    if (version == 4) {
        const size_t end = s.find('\0', at);
        if (end == std::string::npos) throw InputError(path, "unterminated shape name");
        mesh.name = s.substr(at, end - at);
        at = end + 1;
    }
    if (mesh.name.empty()) mesh.name = std::filesystem::path(path).stem().string();
    need(16);
    const uint64_t vertices = read_le<uint64_t>(s, at);
    const uint64_t triangles = read_le<uint64_t>(s, at + 8);
    at += 16;
    if (vertices > kMaxVertices || triangles > kMaxTriangles || vertices == 0 || triangles == 0)
        throw InputError(path, "shape " + std::to_string(shape_index) + " has " +
                                   std::to_string(vertices) + " vertices and " +
                                   std::to_string(triangles) + " triangles");
    const bool doubles = (flags & kDouble) != 0;
    if (doubles == ((flags & kSingle) != 0))
        throw InputError(path, "the flags name neither single nor double precision");
    const size_t real = doubles ? 8 : 4;
    const auto read_reals = [&](size_t n) {
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
    };
    const std::vector<float> p = read_reals(size_t(vertices) * 3);
    for (size_t i = 0; i < vertices; ++i)
        mesh.positions.emplace_back(p[3 * i], p[3 * i + 1], p[3 * i + 2]);
    if (flags & kHasNormals) {
        const std::vector<float> n = read_reals(size_t(vertices) * 3);
        for (size_t i = 0; i < vertices; ++i)
            mesh.normals.emplace_back(n[3 * i], n[3 * i + 1], n[3 * i + 2]);
    }
    if (flags & kHasUvs) {
        const std::vector<float> uv = read_reals(size_t(vertices) * 2);
        for (size_t i = 0; i < vertices; ++i)
            mesh.uv0.emplace_back(uv[2 * i], uv[2 * i + 1]);
    }
    if (flags & kHasColors) read_reals(size_t(vertices) * 3);  // not used by any BSDF we map
    const bool wide = vertices > uint64_t(UINT32_MAX);
    need(triangles * 3 * (wide ? 8 : 4));
    mesh.indices.resize(size_t(triangles) * 3);
    for (size_t i = 0; i < mesh.indices.size(); ++i) {
        const uint64_t index =
            wide ? read_le<uint64_t>(s, at + i * 8) : read_le<uint32_t>(s, at + i * 4);
        if (index >= vertices)
            throw InputError(path, "shape " + std::to_string(shape_index) + ": index " +
                                       std::to_string(index) + " is out of range");
        mesh.indices[i] = uint32_t(index);
    }
    if (face_normals) *face_normals = (flags & kFaceNormals) != 0;
    return mesh;
}

}  // namespace mvpl::scene::mitsuba
