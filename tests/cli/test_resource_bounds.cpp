// Bounds on memory (issue 19): `mvpl render` streams its VPLs chunk by chunk, so that peak memory
// does not grow with --vpls; options whose images cannot fit are refused up front with the
// estimate; and an image that is black because of the scene says so, even under --quiet.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

#include "tests/cli/run_command.h"

namespace mvpl {
namespace {

using test::expect_one_line_error;

const std::string kCbox = MVPL_ASSETS_DIR "/cornell-box/cbox.gltf";

struct PeakRss {
    long kilobytes = 0;
    bool finished = false;  // exited by itself before the deadline
    int exit_code = -1;
};

// Runs `mvpl ARGS` with its output discarded; stops it after `seconds` if it is still running.
// The peak resident set comes from wait4, which reports it for a killed child too.
PeakRss run_for(const std::vector<std::string>& args, double seconds) {
    std::vector<std::string> argv_strings{MVPL_EXE};
    argv_strings.insert(argv_strings.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& a : argv_strings)
        argv.push_back(a.data());
    argv.push_back(nullptr);
    const pid_t pid = ::fork();
    if (pid == 0) {
        const std::string asan =
            std::string(std::getenv("ASAN_OPTIONS") ? std::getenv("ASAN_OPTIONS") : "") +
            ":detect_leaks=0";  // lavapipe's JIT (run_command.h)
        ::setenv("ASAN_OPTIONS", asan.c_str(), 1);
        if (!std::freopen("/dev/null", "w", stdout) || !std::freopen("/dev/null", "w", stderr))
            ::_exit(126);
        ::execv(argv[0], argv.data());
        ::_exit(127);
    }
    PeakRss result;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    int status = 0;
    rusage usage{};
    while (std::chrono::steady_clock::now() < deadline) {
        if (::wait4(pid, &status, WNOHANG, &usage) == pid) {
            result.finished = true;
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    if (!result.finished) {
        ::kill(pid, SIGKILL);
        ::wait4(pid, &status, 0, &usage);
    }
    result.kilobytes = usage.ru_maxrss;
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return result;
}

// Before streaming, 10⁸ light paths were traced into one vector before the first was shaded:
// gigabytes after a few seconds. Now a render of 10⁸ holds one chunk at a time, so that its peak
// after several seconds — well past the start-up and into the first chunks — stays near the peak
// of a whole 10⁴-path render with the same image and shadow sizes (the acceptance bound: 1.5×).
TEST(ResourceBounds, PeakMemoryDoesNotGrowWithTheVplCount) {
    const std::string out = testing::TempDir() + "resource_bounds.exr";
    auto args = [&](const std::string& vpls) {
        return std::vector<std::string>{"render",       kCbox, "--vpls",  vpls, "--res", "16x16",
                                        "--shadow-res", "16",  "--quiet", "-o", out};
    };
    const PeakRss small = run_for(args("10000"), 300.0);
    ASSERT_TRUE(small.finished);
    ASSERT_EQ(small.exit_code, 0);
    const PeakRss large = run_for(args("100000000"), 8.0);
    ASSERT_FALSE(large.finished) << "10^8 paths cannot be done in 8 s: it ended with exit code "
                                 << large.exit_code;
    EXPECT_LE(double(large.kilobytes), 1.5 * double(small.kilobytes))
        << "peak RSS: --vpls 1e8 (after 8 s) " << large.kilobytes << " KB, --vpls 1e4 "
        << small.kilobytes << " KB";
    std::remove(out.c_str());
}

// A resolution, shadow resolution and batch whose images need more than any machine here has
// (16384² × 8 RGBA32F G-buffer layers alone are 34 GB; 4096² × 6 × 256 shadow faces 103 GB) are
// refused before anything is sampled, with the estimate.
TEST(ResourceBounds, ImagesThatCannotFitAreRefusedWithTheEstimate) {
    const test::CommandResult r = test::run_mvpl_gpu(
        "render " + kCbox +
        " --vpls 100 --res 16384x16384 --shadow-res 4096 --batch 256 -o /tmp/never.exr");
    expect_one_line_error(r, "a 16384x16384 image with 4096² shadow faces and 256 VPLs a batch");
    EXPECT_NE(r.err.find(" GB"), std::string::npos) << r.err;
}

// Max depth 1 shows emitters only: a scene lit by punctual lights alone renders black, and says
// so on stderr although --quiet silences progress and the summary.
TEST(ResourceBounds, ABlackImageIsExplainedEvenUnderQuiet) {
    const std::string out = testing::TempDir() + "black.exr";
    const test::CommandResult r =
        test::run_mvpl_gpu("render " MVPL_TEST_DATA_DIR
                           "/gltf/lights_camera.gltf --max-depth 1 --vpls 64 --res 8x8 "
                           "--quiet -o " +
                           out);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(r.out.empty());
    EXPECT_NE(r.err.find("mvpl: warning: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("the image is black"), std::string::npos) << r.err;
    std::remove(out.c_str());
}

}  // namespace
}  // namespace mvpl
