#include "tools/cli/output_check.h"

#include <algorithm>
#include <filesystem>

#include "engine/core/error.h"

namespace mvpl::cli {

void check_output_extensions(const std::vector<std::string>& outputs) {
    for (const std::string& out : outputs) {
        std::string ext = std::filesystem::path(out).extension().string();
        std::transform(ext.begin(), ext.end(), ext.begin(),
                       [](unsigned char c) { return std::tolower(c); });
        if (ext != ".exr" && ext != ".png")
            throw UsageError(out + ": unknown image extension (use .exr or .png)");
    }
}

}  // namespace mvpl::cli
