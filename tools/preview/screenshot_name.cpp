#include "tools/preview/screenshot_name.h"

#include <algorithm>
#include <cstdio>

namespace mvpl::preview {

std::filesystem::path next_screenshot(const std::filesystem::path& folder, const std::string& stem,
                                      uint32_t* number) {
    for (uint32_t n = std::max(*number, 1u);; ++n) {
        char digits[16];
        std::snprintf(digits, sizeof digits, "-%04u", n);
        const std::filesystem::path base = folder / (stem + digits);
        std::error_code ignored;
        if (std::filesystem::exists(base.string() + ".png", ignored) ||
            std::filesystem::exists(base.string() + ".exr", ignored))
            continue;
        *number = n + 1;
        return base;
    }
}

}  // namespace mvpl::preview
