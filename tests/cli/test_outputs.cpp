// Outputs are checked before any rendering and written whole or not at all (issue 19): a missing
// folder costs nothing and names the path, several -o are all written or none, and a file-size
// limit (as a full disk) leaves no partial file and an existing image as it was.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/cli/run_command.h"

namespace mvpl {
namespace {

using test::expect_one_line_error;

namespace fs = std::filesystem;
using test::shell_quote;

const std::string kCbox = MVPL_ASSETS_DIR "/cornell-box/cbox.gltf";

fs::path fresh_dir(const std::string& name) {
    const fs::path dir =
        fs::temp_directory_path() / ("mvpl_outputs_" + std::to_string(::getpid()) + "_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string read(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

TEST(Outputs, AMissingFolderIsRefusedBeforeRendering) {
    for (const std::string& command :
         {"render " + kCbox + " --vpls 100000", "reference " + kCbox + " --spp 4096",
          "vpls " + kCbox + " --vpls 100000"}) {
        const test::CommandResult r = test::run_mvpl_gpu(command + " -o /nonexistent/x.png");
        expect_one_line_error(r, "/nonexistent/x.png: cannot be written: the folder /nonexistent");
        EXPECT_TRUE(r.out.empty()) << command;  // no summary: nothing was rendered
    }
    const fs::path dir = fresh_dir("folder");
    expect_one_line_error(test::run_mvpl("reference " + kCbox + " --spp 1 --res 8x8 -o " +
                                         shell_quote(dir.string() + "/.png")),
                          "unknown image extension");
    fs::create_directories(dir / "taken.png");
    expect_one_line_error(test::run_mvpl("reference " + kCbox + " --spp 1 --res 8x8 -o " +
                                         shell_quote((dir / "taken.png").string())),
                          "it is a folder");
    fs::remove_all(dir);
}

TEST(Outputs, SeveralOutputsAreAllWrittenOrNone) {
    const fs::path dir = fresh_dir("all_or_none");
    const fs::path good = dir / "good.exr";
    // The second output cannot be written: the first must not appear either (the write itself
    // is all-or-none too: tests/core/test_image.cpp).
    const std::string args = "reference " + kCbox + " --spp 1 --res 16x16 --quiet -o " +
                             shell_quote(good.string()) + " -o " +
                             shell_quote((dir / "sub" / "b.png").string());
    expect_one_line_error(test::run_mvpl(args), "sub/b.png");
    EXPECT_FALSE(fs::exists(good));
    EXPECT_TRUE(fs::is_empty(dir));
    fs::remove_all(dir);
}

// bash's ulimit -f counts 1024-byte blocks: 8 KB is far below a 96×96 float EXR (108 KB).
TEST(Outputs, AFileSizeLimitLeavesNoPartialFileAndKeepsTheOldImage) {
    const fs::path dir = fresh_dir("full_disk");
    const fs::path exr = dir / "image.exr";
    const fs::path png = dir / "image.png";
    { std::ofstream(png, std::ios::binary) << "the old image"; }
    const test::CommandResult r = test::run_mvpl_env(
        "ulimit -f 8;", "reference " + kCbox + " --spp 1 --res 96x96 --quiet -o " +
                            shell_quote(exr.string()) + " -o " + shell_quote(png.string()));
    expect_one_line_error(r, exr.string() + ": cannot be written");
    EXPECT_FALSE(fs::exists(exr));
    EXPECT_EQ(read(png), "the old image");
    // No temporary is left beside the targets.
    size_t files = 0;
    for ([[maybe_unused]] const fs::directory_entry& e : fs::directory_iterator(dir))
        ++files;
    EXPECT_EQ(files, 1u);
    fs::remove_all(dir);
}

}  // namespace
}  // namespace mvpl

namespace mvpl {
namespace {

// Without -o the command picks the file's name itself, and says it (issue 12, item 4).
TEST(Outputs, WithoutOutputTheCommandSaysWhichFileItWrote) {
    const fs::path dir = fresh_dir("default_output");
    const test::CommandResult r = test::run_mvpl_env("cd " + shell_quote(dir.string()) + " &&",
                                                     "reference " + kCbox + " --spp 1 --res 8x8");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out.rfind("reference: wrote reference.exr\n", 0), 0u) << r.out;
    EXPECT_TRUE(fs::is_regular_file(dir / "reference.exr"));
    // --quiet keeps stdout empty; an explicit -o is not announced.
    const test::CommandResult quiet =
        test::run_mvpl_env("cd " + shell_quote(dir.string()) + " &&",
                           "reference " + kCbox + " --spp 1 --res 8x8 --quiet");
    EXPECT_TRUE(quiet.out.empty()) << quiet.out;
    const test::CommandResult named = test::run_mvpl(
        "reference " + kCbox + " --spp 1 --res 8x8 -o " + shell_quote((dir / "n.exr").string()));
    EXPECT_EQ(named.out.find("wrote"), std::string::npos) << named.out;
    fs::remove_all(dir);
}

}  // namespace
}  // namespace mvpl
