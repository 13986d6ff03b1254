#include "engine/core/regular_file.h"

#include <filesystem>

#include "engine/core/error.h"

namespace mvpl {

namespace fs = std::filesystem;

void require_regular_file(const std::string& path) {
    std::error_code error;
    const fs::file_status status = fs::status(path, error);
    if (status.type() == fs::file_type::not_found) throw InputError(path, "file not found");
    if (error) throw InputError(path, "cannot access the file (" + error.message() + ")");
    switch (status.type()) {
        case fs::file_type::regular:
            break;
        case fs::file_type::directory:
            throw InputError(path, "is a directory, not a file");
        case fs::file_type::fifo:
            throw InputError(path, "is a FIFO (named pipe), not a regular file");
        case fs::file_type::socket:
            throw InputError(path, "is a socket, not a regular file");
        case fs::file_type::block:
        case fs::file_type::character:
            throw InputError(path, "is a device, not a regular file");
        default:
            throw InputError(path, "is not a regular file");
    }
    // Kernel pseudo-files pass as regular files but may never end (/proc/kcore).
    const std::string real = fs::weakly_canonical(path, error).string();
    if (real.starts_with("/proc/") || real.starts_with("/sys/"))
        throw InputError(path, "is a kernel pseudo-file, not a regular file");
}

}  // namespace mvpl
