#include "engine/scene/gltf_document.h"

#include <algorithm>
#include <climits>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <new>
#include <optional>
#include <vector>

#include "engine/scene/gltf_diagnose.h"

namespace mvpl::scene::gltf {
namespace {

// tinygltf measures files in unsigned int; refusing larger files up front also bounds what a
// hostile URI can make us read.
constexpr uint64_t kMaxFileBytes = uint64_t(1) << 31;
// tinygltf turns extras and extensions into its Value tree recursively: deep nesting would
// overflow the stack long before it could mean anything.
constexpr int kMaxJsonDepth = 64;
constexpr size_t kMaxMessageChars = 400;

constexpr uint32_t kGlbMagic = 0x46546C67;      // "glTF"
constexpr uint32_t kGlbChunkJson = 0x4E4F534A;  // "JSON"
constexpr uint32_t kGlbChunkBin = 0x004E4942;   // "BIN\0"

const char* const kSupportedExtensions[] = {
    "KHR_materials_emissive_strength",
    "KHR_materials_specular",
    "KHR_materials_ior",
    "KHR_texture_transform",
    "KHR_lights_punctual",
    "KHR_materials_transmission",
    "KHR_materials_volume",
    "KHR_materials_unlit",
    "KHR_materials_pbrSpecularGlossiness",
};

// Reads a whole regular file; `error` says why not in a few words. Devices and FIFOs are refused
// so that a URI such as /dev/stdin cannot make the loader hang.
bool read_whole_file(const std::string& path, std::vector<unsigned char>& out, std::string& error) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (status.type() == fs::file_type::not_found) {
        error = "file not found";
        return false;
    }
    if (ec) {
        error = "cannot access the file (" + ec.message() + ")";
        return false;
    }
    if (fs::is_directory(status)) {
        error = "is a directory, not a file";
        return false;
    }
    if (!fs::is_regular_file(status)) {
        error = "is not a regular file";
        return false;
    }
    const uintmax_t size = fs::file_size(path, ec);
    if (ec) {
        error = "cannot read the file size (" + ec.message() + ")";
        return false;
    }
    if (size > kMaxFileBytes) {
        error = "file is larger than 2 GiB";
        return false;
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        error = "cannot open the file";
        return false;
    }
    out.resize(size_t(size));
    if (size > 0) in.read(reinterpret_cast<char*>(out.data()), std::streamsize(size));
    if (uintmax_t(in.gcount()) != size) {
        error = "cannot read the file";
        return false;
    }
    return true;
}

// tinygltf also looks for external files relative to the working directory; accepting only the
// absolute paths it builds from our absolute base directory keeps a scene from picking up
// unrelated files there.
bool fs_file_exists(const std::string& path, void*) {
    std::error_code ec;
    return std::filesystem::path(path).is_absolute() && std::filesystem::is_regular_file(path, ec);
}

std::string fs_expand_path(const std::string& path, void*) {
    return path;
}

bool fs_read_whole_file(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                        void*) {
    std::string why;
    if (read_whole_file(path, *out, why)) return true;
    if (err) *err += why;
    return false;
}

bool fs_write_whole_file(std::string* err, const std::string&, const std::vector<unsigned char>&,
                         void*) {
    if (err) *err += "the scene loader never writes files";
    return false;
}

struct ImageLoadState {
    const tinygltf::Model* model = nullptr;
    std::string error;  // the first precise error, preferred over tinygltf's message
};

// Keeps the encoded bytes; images are decoded later, only when a material uses them, with size
// limits checked first (see gltf_textures.cpp).
bool keep_encoded_image(tinygltf::Image* image, const int index, std::string* err, std::string*,
                        int, int, const unsigned char* bytes, int size, void* user_data) {
    auto& state = *static_cast<ImageLoadState*>(user_data);
    auto reject = [&](const std::string& what) {
        if (state.error.empty()) state.error = what;
        if (err) *err += what + "\n";
        return false;
    };
    const std::string name = "image " + std::to_string(index);
    if (image->bufferView >= 0) {
        // tinygltf hands us a pointer into the buffer without checking that the view fits it.
        const auto& views = state.model->bufferViews;
        const auto& buffers = state.model->buffers;
        if (size_t(image->bufferView) >= views.size()) {
            return reject(name + " refers to buffer view " + std::to_string(image->bufferView) +
                          ", but the file has " + std::to_string(views.size()) + " buffer views");
        }
        const tinygltf::BufferView& view = views[size_t(image->bufferView)];
        if (view.buffer < 0 || size_t(view.buffer) >= buffers.size()) {
            return reject("buffer view " + std::to_string(image->bufferView) +
                          " refers to buffer " + std::to_string(view.buffer) +
                          ", but the file has " + std::to_string(buffers.size()) + " buffers");
        }
        const size_t buffer_size = buffers[size_t(view.buffer)].data.size();
        if (view.byteOffset > buffer_size || view.byteLength > buffer_size - view.byteOffset) {
            return reject("buffer view " + std::to_string(image->bufferView) + " of " + name +
                          " (offset " + std::to_string(view.byteOffset) + ", length " +
                          std::to_string(view.byteLength) + ") extends past the end of buffer " +
                          std::to_string(view.buffer) + " (" + std::to_string(buffer_size) +
                          " bytes)");
        }
        if (view.byteLength > size_t(INT_MAX)) return reject(name + " is larger than 2 GiB");
    }
    if (bytes == nullptr || size <= 0) return reject(name + " has no data");
    image->image.assign(bytes, bytes + size);
    image->as_is = true;
    return true;
}

uint32_t read_u32(const std::vector<unsigned char>& bytes, size_t offset) {
    return uint32_t(bytes[offset]) | uint32_t(bytes[offset + 1]) << 8 |
           uint32_t(bytes[offset + 2]) << 16 | uint32_t(bytes[offset + 3]) << 24;
}

struct Layout {
    size_t length = 0;  // bytes to hand to tinygltf
    size_t json_offset = 0;
    size_t json_length = 0;
    std::optional<uint64_t> bin_length;
};

// Checks the GLB container (tinygltf 2.7 reads up to 8 bytes past a BIN chunk whose length
// overruns the file) and finds its chunks.
Layout check_glb(const Document& doc, const std::vector<unsigned char>& bytes) {
    const size_t size = bytes.size();
    if (size < 12) {
        doc.fail("truncated GLB: the 12-byte header is incomplete (" + std::to_string(size) +
                 " bytes)");
    }
    const uint32_t version = read_u32(bytes, 4);
    if (version != 2) doc.fail("GLB version " + std::to_string(version) + " is not supported");
    const uint32_t length = read_u32(bytes, 8);
    if (length > size) {
        doc.fail("truncated GLB: the header declares " + std::to_string(length) +
                 " bytes, the file has " + std::to_string(size));
    }
    if (length < 20) doc.fail("truncated GLB: there is no JSON chunk");
    const uint64_t json_chunk_length = read_u32(bytes, 12);
    if (read_u32(bytes, 16) != kGlbChunkJson) doc.fail("the first GLB chunk is not JSON");
    if (json_chunk_length == 0) doc.fail("the GLB JSON chunk is empty");
    const uint64_t json_end = 20 + json_chunk_length;
    if (json_end > length) {
        doc.fail("the GLB JSON chunk (" + std::to_string(json_chunk_length) +
                 " bytes at offset 20) runs past the end of the file (" + std::to_string(length) +
                 " bytes)");
    }
    Layout layout{length, 20, size_t(json_chunk_length), std::nullopt};
    if (json_end < length) {
        if (json_end + 8 > length) doc.fail("truncated GLB: the BIN chunk header is incomplete");
        const uint64_t bin_length = read_u32(bytes, size_t(json_end));
        layout.bin_length = bin_length;
        if (json_end + 8 + bin_length > length) {
            doc.fail("the GLB BIN chunk (" + std::to_string(bin_length) + " bytes at offset " +
                     std::to_string(json_end + 8) + ") runs past the end of the file (" +
                     std::to_string(length) + " bytes)");
        }
        if (read_u32(bytes, size_t(json_end) + 4) != kGlbChunkBin) {
            doc.fail("the second GLB chunk is not a BIN chunk");
        }
    }
    return layout;
}

int json_depth(const unsigned char* text, size_t length) {
    int depth = 0;
    int deepest = 0;
    bool in_string = false;
    bool escaped = false;
    for (size_t i = 0; i < length; ++i) {
        const unsigned char c = text[i];
        if (in_string) {
            if (escaped) {
                escaped = false;
            } else if (c == '\\') {
                escaped = true;
            } else if (c == '"') {
                in_string = false;
            }
        } else if (c == '"') {
            in_string = true;
        } else if (c == '{' || c == '[') {
            deepest = std::max(deepest, ++depth);
            if (deepest > kMaxJsonDepth) return deepest;
        } else if (c == '}' || c == ']') {
            --depth;
        }
    }
    return deepest;
}

void check_required_extensions(const Document& doc, const std::vector<std::string>& required) {
    for (const std::string& name : required) {
        if (!is_supported_extension(name))
            doc.fail("required extension " + name + " is not supported");
    }
}

void check_asset_and_extensions(const Document& doc) {
    const std::string& version = doc.model.asset.version;
    if (version.empty() || version[0] != '2') {
        doc.fail("glTF version '" + version + "' is not supported (only 2.x)");
    }
    check_required_extensions(doc, doc.model.extensionsRequired);
}

}  // namespace

bool is_supported_extension(const std::string& name) {
    return std::any_of(std::begin(kSupportedExtensions), std::end(kSupportedExtensions),
                       [&](const char* s) { return name == s; });
}

std::string one_line(const std::string& message) {
    size_t begin = 0;
    std::string line;
    while (begin < message.size() && line.empty()) {
        size_t end = message.find_first_of("\r\n", begin);
        if (end == std::string::npos) end = message.size();
        line = message.substr(begin, end - begin);
        const size_t first = line.find_first_not_of(" \t");
        const size_t last = line.find_last_not_of(" \t");
        line = first == std::string::npos ? std::string() : line.substr(first, last - first + 1);
        begin = end + 1;
    }
    // nlohmann's "[json.exception.parse_error.101] parse error at ..." reads better as this.
    if (line.rfind("[json.exception.", 0) == 0) {
        const size_t tag_end = line.find("] ");
        if (tag_end != std::string::npos) line = "invalid JSON: " + line.substr(tag_end + 2);
    }
    // tinygltf quotes whole data URIs in some messages.
    for (size_t at = line.find("data:"); at != std::string::npos; at = line.find("data:", at + 1)) {
        const size_t end = line.find_first_of(" \"'", at);
        line.replace(at, end == std::string::npos ? std::string::npos : end - at, "(data URI)");
    }
    if (line.empty()) line = "tinygltf rejected the file without saying why";
    return printable(line);
}

std::string printable(const std::string& what) {
    std::string out =
        what.size() > kMaxMessageChars ? what.substr(0, kMaxMessageChars) + "..." : what;
    for (char& c : out) {
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F) c = ' ';
    }
    return out;
}

Document read_document(const std::string& path) {
    Document doc;
    doc.path = path;

    std::vector<unsigned char> bytes;
    std::string why;
    if (!read_whole_file(path, bytes, why)) doc.fail(why);
    if (bytes.empty()) doc.fail("file is empty");

    const bool binary = bytes.size() >= 4 && read_u32(bytes, 0) == kGlbMagic;
    const Layout layout =
        binary ? check_glb(doc, bytes) : Layout{bytes.size(), 0, bytes.size(), std::nullopt};
    const char* json = reinterpret_cast<const char*>(bytes.data()) + layout.json_offset;
    if (json_depth(bytes.data() + layout.json_offset, layout.json_length) > kMaxJsonDepth) {
        doc.fail("JSON is nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    }

    std::error_code ec;
    const std::filesystem::path absolute = std::filesystem::absolute(path, ec);
    const std::string base_dir = ec ? std::string() : absolute.parent_path().string();
    doc.base_dir = base_dir;

    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks(tinygltf::FsCallbacks{
        &fs_file_exists, &fs_expand_path, &fs_read_whole_file, &fs_write_whole_file, nullptr});
    ImageLoadState image_state{&doc.model, {}};
    loader.SetImageLoader(&keep_encoded_image, &image_state);

    std::string err;
    std::string warn;
    bool ok = false;
    try {
        if (binary) {
            ok = loader.LoadBinaryFromMemory(&doc.model, &err, &warn, bytes.data(),
                                             unsigned(layout.length), base_dir);
        } else {
            ok = loader.LoadASCIIFromString(&doc.model, &err, &warn, json, unsigned(layout.length),
                                            base_dir);
        }
    } catch (const std::bad_alloc&) {
        doc.fail("out of memory while parsing the glTF");
    } catch (const std::exception& e) {
        doc.fail("glTF parse error: " + one_line(e.what()));
    }
    if (!ok) {
        // An unsupported extension the file requires explains whatever else tinygltf found.
        check_required_extensions(doc, required_extensions(json, layout.json_length));
        if (!image_state.error.empty()) doc.fail(image_state.error);
        const std::string buffer_problem =
            diagnose_buffer(json, layout.json_length, doc.model.buffers.size(), base_dir, binary,
                            layout.bin_length);
        doc.fail(buffer_problem.empty() ? one_line(err) : buffer_problem);
    }
    check_asset_and_extensions(doc);
    return doc;
}

}  // namespace mvpl::scene::gltf
