#include "tests/window/preview_run.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace mvpl::test {

std::filesystem::path preview_temp_dir() {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("mvpl_window_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return dir;
}

bool have_xvfb() {
    return std::system("command -v xvfb-run >/dev/null 2>&1") == 0;
}

// A 24-bit screen (xvfb-run's default of 8 bits offers the Vulkan WSI no usable visual), on a
// server number that starts from this process's id: `xvfb-run -a` alone races when ctest -j
// starts two of these tests at once (both take the first free number, 99).
std::string xvfb() {
    static int counter = 0;
    const int server = 100 + int((::getpid() * 7 + counter++) % 800);
    return "xvfb-run -a -n " + std::to_string(server) + " -s '-screen 0 1024x768x24'";
}

CommandResult run_preview(const std::string& args, const std::string& folder) {
    const std::string chdir = folder.empty() ? "" : " env -C " + shell_quote(folder);
    return run_mvpl_gpu("preview " + args, xvfb() + chdir);
}

size_t channels_differing(const Image& a, const Image& b, size_t* lit) {
    if (a.width() != b.width() || a.height() != b.height()) return size_t(-1);
    size_t bad = 0, positive = 0;
    for (size_t i = 0; i < a.pixels().size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            const double x = a.pixels()[i][c], y = b.pixels()[i][c];
            positive += y > 0.0;
            bad += std::abs(x - y) > 1e-5 * std::max(std::abs(x), std::abs(y));
        }
    }
    if (lit) *lit = positive;
    return bad;
}

}  // namespace mvpl::test
