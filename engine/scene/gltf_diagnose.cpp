#include "engine/scene/gltf_diagnose.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>

namespace mvpl::scene::gltf {
namespace {

// The data URI prefixes tinygltf 2.7 decodes for buffers.
const char* const kDataUriHeaders[] = {
    "data:application/octet-stream;base64,",
    "data:application/gltf-buffer;base64,",
    "data:image/jpeg;base64,",
    "data:image/png;base64,",
    "data:image/bmp;base64,",
    "data:image/gif;base64,",
    "data:text/plain;base64,",
};

bool is_base64(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '+' ||
           c == '/';
}

// Bytes tinygltf's decoder yields: it stops at the first '=' or foreign character.
uint64_t decoded_length(const std::string& uri, size_t payload_start) {
    uint64_t chars = 0;
    for (size_t i = payload_start; i < uri.size() && is_base64(uri[i]); ++i)
        ++chars;
    const uint64_t tail = chars % 4;
    return chars / 4 * 3 + (tail > 0 ? tail - 1 : 0);
}

// As tinygltf decodes URIs ('%XX' escapes, '+' as space).
std::string url_decode(const std::string& uri) {
    auto hex = [](char c) -> int {
        if (c >= '0' && c <= '9') return c - '0';
        if (c >= 'a' && c <= 'f') return c - 'a' + 10;
        if (c >= 'A' && c <= 'F') return c - 'A' + 10;
        return 0;
    };
    std::string out;
    for (size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '+') {
            out += ' ';
        } else if (uri[i] == '%' && i + 2 < uri.size()) {
            out += char(hex(uri[i + 1]) << 4 | hex(uri[i + 2]));
            i += 2;
        } else {
            out += uri[i];
        }
    }
    return out;
}

// Joined as tinygltf joins them, so that both look at the same file.
std::string joined_path(const std::string& base_dir, const std::string& uri) {
    return base_dir.empty() ? url_decode(uri) : base_dir + "/" + url_decode(uri);
}

std::string check_buffer(const nlohmann::json& buffer, size_t index, const std::string& base_dir,
                         bool binary, std::optional<uint64_t> bin_chunk_bytes) {
    const std::string name = "buffer " + std::to_string(index);
    if (!buffer.is_object()) return name + " is not a JSON object";
    const auto length_it = buffer.find("byteLength");
    if (length_it == buffer.end()) return name + " has no byteLength";
    if (!length_it->is_number_unsigned()) {
        return name + " byteLength " + length_it->dump() + " is not a non-negative integer";
    }
    const uint64_t length = length_it->get<uint64_t>();
    const auto uri_it = buffer.find("uri");
    if (uri_it == buffer.end() || (uri_it->is_string() && uri_it->get<std::string>().empty())) {
        if (!binary) return name + " has no uri";
        if (!bin_chunk_bytes) return name + " has no uri and the GLB has no BIN chunk";
        if (length > *bin_chunk_bytes) {
            return name + " byteLength " + std::to_string(length) + " exceeds the " +
                   std::to_string(*bin_chunk_bytes) + "-byte GLB BIN chunk";
        }
        return {};
    }
    if (!uri_it->is_string()) return name + " uri is not a string";
    const std::string uri = uri_it->get<std::string>();
    if (uri.rfind("data:", 0) == 0) {
        for (const char* header : kDataUriHeaders) {
            const std::string prefix = header;
            if (uri.rfind(prefix, 0) != 0) continue;
            const uint64_t decoded = decoded_length(uri, prefix.size());
            if (decoded == 0) return name + " has an empty data URI";
            if (decoded != length) {
                return name + " byteLength " + std::to_string(length) + " does not match the " +
                       std::to_string(decoded) + " bytes of its data URI";
            }
            return {};
        }
        return name + " has a data URI that is not base64 of a known media type";
    }
    const std::string problem = external_file_problem(base_dir, uri);
    if (!problem.empty()) return name + " file '" + uri + "' " + problem;
    std::error_code ec;
    const uintmax_t size = std::filesystem::file_size(joined_path(base_dir, uri), ec);
    if (!ec && size != length) {
        return name + " file '" + uri + "' has " + std::to_string(size) +
               " bytes, but byteLength says " + std::to_string(length);
    }
    return {};
}

}  // namespace

std::string external_file_problem(const std::string& base_dir, const std::string& uri) {
    const std::string path = joined_path(base_dir, uri);
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (!std::filesystem::exists(status)) return "not found";
    if (std::filesystem::is_directory(status)) return "is a directory, not a file";
    if (!std::filesystem::is_regular_file(status)) return "is not a regular file";
    errno = 0;
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (file == nullptr) {
        return std::string("cannot be opened (") + (errno ? std::strerror(errno) : "unknown") + ")";
    }
    std::fclose(file);
    return {};
}

std::vector<std::string> required_extensions(const char* json, size_t json_length) {
    const nlohmann::json doc = nlohmann::json::parse(json, json + json_length, nullptr, false);
    std::vector<std::string> names;
    if (!doc.is_object()) return names;
    const auto required = doc.find("extensionsRequired");
    if (required == doc.end() || !required->is_array()) return names;
    for (const auto& name : *required) {
        if (name.is_string()) names.push_back(name.get<std::string>());
    }
    return names;
}

std::string diagnose_buffer(const char* json, size_t json_length, size_t index,
                            const std::string& base_dir, bool binary,
                            std::optional<uint64_t> bin_chunk_bytes) {
    const nlohmann::json doc = nlohmann::json::parse(json, json + json_length, nullptr, false);
    if (!doc.is_object()) return {};
    const auto buffers = doc.find("buffers");
    if (buffers == doc.end() || !buffers->is_array() || index >= buffers->size()) return {};
    return check_buffer((*buffers)[index], index, base_dir, binary, bin_chunk_bytes);
}

}  // namespace mvpl::scene::gltf
