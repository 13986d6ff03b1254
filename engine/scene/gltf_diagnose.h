#pragma once
// Precise reasons for the buffer problems that tinygltf reports vaguely ("Failed to decode
// 'uri'"). Runs only after tinygltf has refused a file, so a valid scene never pays for it.
#include <cstdint>
#include <optional>
#include <string>

namespace mvpl::scene::gltf {

// What is wrong with buffer `index` (its byteLength, data URI, external file or the GLB BIN
// chunk), or an empty string. tinygltf stops at the first buffer it cannot load, so `index` is
// the number of buffers it did load. `bin_chunk_bytes` is the BIN chunk's length for a GLB that
// has one.
std::string diagnose_buffer(const char* json, size_t json_length, size_t index,
                            const std::string& base_dir, bool binary,
                            std::optional<uint64_t> bin_chunk_bytes);

}  // namespace mvpl::scene::gltf
