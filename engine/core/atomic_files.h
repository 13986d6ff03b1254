#pragma once
// Files that appear whole or not at all: each is written to a temporary file beside its target
// (same folder, so that rename(2) replaces it atomically) and renamed into place only when every
// one of them is complete. A failure — a full disk, a file-size limit, an unwritable folder —
// removes the temporaries and leaves the targets as they were (a file that existed keeps its old
// content), so an interrupted or failed run never leaves a truncated image behind.
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace mvpl {

// write(i, temp) writes target i's content into the file `temp` (which exists, empty) and throws
// a std::exception saying why on failure. Throws InputError naming the target that could not be
// written and why. Should the renames themselves fail part-way (they do not on one file system
// short of a crash), the targets renamed so far keep their new content.
void write_files_atomically(const std::vector<std::string>& targets,
                            const std::function<void(size_t, const std::string&)>& write);

// Writes `bytes` to `path` with every write, flush and close checked; throws std::runtime_error
// with the system's reason (a full disk shows at the write or only at the close).
void write_bytes(const std::string& path, std::span<const uint8_t> bytes);

}  // namespace mvpl
