// Mitsuba XML on the command line (issue 16): -D and -a as Mitsuba's, the file's film size and
// integrator depth as the defaults of --res and --max-depth (the options override them), and bad
// XML refused in one line naming FILE:LINE with exit code 2.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "engine/core/image.h"
#include "tests/cli/run_command.h"

namespace mvpl {
namespace {

namespace fs = std::filesystem;
using test::expect_one_line_error;
using test::run_mvpl;
using test::shell_quote;

const std::string kCbox = std::string(MVPL_TEST_DATA_DIR) + "/mitsuba/cbox.xml";

fs::path temp_dir() {
    const fs::path dir = fs::temp_directory_path() / "mvpl_mitsuba_cli";
    fs::create_directories(dir);
    return dir;
}

TEST(MitsubaCli, FilmAndIntegratorAreTheDefaultsAndOptionsOverrideThem) {
    const std::string out = (temp_dir() / "cbox.exr").string();
    // cbox.xml: film $res × $res with <default name="res" value="64"/>, max_depth 4.
    auto r = run_mvpl("reference " + shell_quote(kCbox) + " --spp 1 -o " + shell_quote(out));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("64x64"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("max depth 4"), std::string::npos) << r.out;
    EXPECT_EQ(read_exr(out).width(), 64);
    r = run_mvpl("reference " + shell_quote(kCbox) + " -D res=20 --spp 1 --max-depth 2 -o " +
                 shell_quote(out));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("20x20"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("max depth 2"), std::string::npos) << r.out;
    r = run_mvpl("reference " + shell_quote(kCbox) + " -Dres=24 --res 30x10 --spp 1 -o " +
                 shell_quote(out));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(read_exr(out).width(), 30);
    EXPECT_EQ(read_exr(out).height(), 10);
}

TEST(MitsubaCli, SearchPathsFindMeshesThatTheScenesFolderLacks) {
    const fs::path meshes = temp_dir() / "elsewhere" / "meshes";
    fs::create_directories(meshes);
    std::ofstream(meshes / "quad.obj") << "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n";
    const fs::path scene = temp_dir() / "uses-quad.xml";
    std::ofstream(scene) << "<scene version=\"3.0.0\">\n<shape type=\"obj\">\n"
                            "<string name=\"filename\" value=\"meshes/quad.obj\"/>\n</shape>\n"
                            "</scene>\n";
    const std::string out = (temp_dir() / "quad.exr").string();
    const std::string common =
        shell_quote(scene.string()) + " --spp 1 --res 8x8 -o " + shell_quote(out);
    expect_one_line_error(run_mvpl("reference " + common),
                          scene.string() + ":3: file 'meshes/quad.obj' not found");
    const auto r =
        run_mvpl("reference " + common + " -a " + shell_quote((meshes.parent_path()).string()));
    EXPECT_EQ(r.exit_code, 0) << r.err;
}

TEST(MitsubaCli, BadXmlIsRefusedInOneLineWithFileAndLine) {
    const std::string bad = std::string(MVPL_TEST_DATA_DIR) + "/bad/";
    const std::pair<const char*, const char*> cases[] = {
        {"mitsuba-unclosed-tag.xml", ":4: malformed XML"},
        {"mitsuba-unknown-reference.xml", ":3: unknown reference 'nope'"},
        {"mitsuba-missing-file.xml", ":3: file 'not-there.obj' not found"},
        {"mitsuba-negative-radius.xml", ":2: sphere radius must be positive"},
        {"mitsuba-nan-matrix.xml", ":4: value 'nan' is not a finite number"},
        {"mitsuba-unsupported-bsdf.xml", ":2: bsdf type 'hair' is not supported"},
    };
    for (const auto& [file, what] : cases) {
        SCOPED_TRACE(file);
        expect_one_line_error(run_mvpl("render " + shell_quote(bad + file) + " --quiet"),
                              bad + file + what);
    }
    expect_one_line_error(run_mvpl("reference " + shell_quote(kCbox) + " -D res"),
                          "-D 'res' is not NAME=VALUE");
}

}  // namespace
}  // namespace mvpl
