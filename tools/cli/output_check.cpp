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

}  // namespace mvpl::cli
