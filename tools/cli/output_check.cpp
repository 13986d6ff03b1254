#include "tools/cli/output_check.h"

#include "engine/core/error.h"
#include "engine/core/file_extension.h"

namespace mvpl::cli {

void check_output_extensions(const std::vector<std::string>& outputs) {
    for (const std::string& out : outputs) {
        const std::string ext = lower_extension(out);
        if (ext != ".exr" && ext != ".png")
            throw UsageError(out + ": unknown image extension (use .exr or .png)");
    }
}

}  // namespace mvpl::cli
