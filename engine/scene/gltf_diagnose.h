#pragma once
// Precise reasons for the buffer problems that tinygltf reports vaguely ("Failed to decode
// 'uri'"). Runs only after tinygltf has refused a file, so a valid scene never pays for it.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace mvpl::scene::gltf {

// What is wrong with buffer `index` (its byteLength, data URI, external file or the GLB BIN
// chunk), or an empty string. tinygltf stops at the first buffer it cannot load, so `index` is
// the number of buffers it did load. `bin_chunk_bytes` is the BIN chunk's length for a GLB that
// has one.
std::string diagnose_buffer(const char* json, size_t json_length, size_t index,
                            const std::string& base_dir, bool binary,
                            std::optional<uint64_t> bin_chunk_bytes);

// The names in the document's extensionsRequired, read from the raw JSON: tinygltf can refuse a
// file for what an extension changes (a Draco primitive's accessors have no buffer view) before
// the loader could say that the extension is the cause. Empty when there are none or the JSON
// does not parse.
std::vector<std::string> required_extensions(const char* json, size_t json_length);

// Why the external file `uri` (relative to `base_dir`, decoded as tinygltf decodes it) cannot be
// read: "not found", "is not a regular file", "cannot be opened (Permission denied)"; empty when
// it can.
std::string external_file_problem(const std::string& base_dir, const std::string& uri);

}  // namespace mvpl::scene::gltf
