#include "tools/cli/output_check.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include "engine/core/error.h"
#include "engine/core/file_extension.h"

namespace mvpl::cli {

void check_outputs(const std::vector<std::string>& outputs) {
    namespace fs = std::filesystem;
    for (const std::string& out : outputs) {
        const std::string ext = lower_extension(out);
        if (ext != ".exr" && ext != ".png")
            throw UsageError(out + ": unknown image extension (use .exr or .png)");
        const fs::path path(out);
        const fs::path dir = path.has_parent_path() ? path.parent_path() : fs::path(".");
        std::error_code ec;
        if (!fs::is_directory(dir, ec))
            throw InputError(out,
                             "cannot be written: the folder " + dir.string() + " does not exist");
        if (fs::is_directory(path, ec)) throw InputError(out, "cannot be written: it is a folder");
        // The image is written beside the target and renamed into place (atomic_files.h): the
        // folder itself must be writable, not only an existing file.
        if (access(dir.c_str(), W_OK | X_OK) != 0)
            throw InputError(out,
                             "cannot be written: the folder " + dir.string() + " is not writable");
    }
}

std::vector<std::string> outputs_or(const std::vector<std::string>& outputs,
                                    const std::string& fallback, bool& defaulted) {
    defaulted = outputs.empty();
    return defaulted ? std::vector<std::string>{fallback} : outputs;
}

void say_written(const std::string& command, const std::vector<std::string>& outputs,
                 bool defaulted, bool quiet) {
    if (defaulted && !quiet && !outputs.empty())
        std::printf("%s: wrote %s\n", command.c_str(), outputs.front().c_str());
}

void create_output_folder(const std::string& folder) {
    namespace fs = std::filesystem;
    // The nearest part of the path that exists says why: a file where a folder must be.
    for (fs::path part = fs::path(folder); !part.empty(); part = part.parent_path()) {
        std::error_code error;
        const fs::file_status status = fs::status(part, error);
        if (status.type() == fs::file_type::not_found) {
            if (part == part.parent_path()) break;
            continue;
        }
        if (!fs::is_directory(status))
            throw InputError(folder, "cannot be a folder: '" + part.string() + "' is a file");
        break;
    }
    std::error_code error;
    fs::create_directories(folder, error);
    if (error) throw InputError(folder, "cannot create the folder (" + error.message() + ")");
}

}  // namespace mvpl::cli
