// Hostile input (issue 32, item 8): files and command lines made to exhaust the stack, memory or
// time, or to hang a reader. Each must end with exit code 2 and one line `mvpl: error: …` naming
// the file, in bounded time: every run goes through `timeout`, so that a hang fails the test
// (exit 124) instead of hanging CI. The big inputs are generated here, not committed.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include "engine/core/image.h"
#include "tests/cli/run_command.h"

namespace mvpl {
namespace {

namespace fs = std::filesystem;
using test::expect_one_line_error;
using test::run_mvpl_env;

const std::string kCbox = MVPL_ASSETS_DIR "/cornell-box/cbox.gltf";
const std::string kBad = MVPL_TEST_DATA_DIR "/bad/";
// Each refusal takes well under a second; this much leaves room for a sanitizer build.
const std::string kBounded = "timeout 60";

// A fresh folder for one test's generated files.
fs::path temp_dir(const std::string& name) {
    const fs::path dir =
        fs::temp_directory_path() / ("mvpl_hostile_" + std::to_string(::getpid()) + "_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

void write_text(const fs::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

test::CommandResult reference(const std::string& scene, const std::string& more = "") {
    return run_mvpl_env(kBounded, "reference " + test::shell_quote(scene) +
                                      " --res 8x8 --spp 1 --quiet -o /tmp/mvpl_hostile.exr " +
                                      more);
}

TEST(HostileInput, XmlNesting20000DeepIsRefused) {
    const fs::path dir = temp_dir("nesting");
    std::string xml = "<scene version=\"3.0.0\">\n";
    for (int i = 0; i < 20000; ++i)
        xml += "<shape>";
    for (int i = 0; i < 20000; ++i)
        xml += "</shape>";
    write_text(dir / "deep.xml", xml + "\n</scene>\n");
    const auto r = reference((dir / "deep.xml").string());
    expect_one_line_error(r, (dir / "deep.xml").string() + ":2: elements nest deeper than");
    fs::remove_all(dir);
}

// fI.xml, built by appending (GCC 12's -Wrestrict misfires on "f" + std::to_string(i)).
std::string fan_out_file(int i) {
    std::string name = "f";
    name.append(std::to_string(i)).append(".xml");
    return name;
}

// 16 files, each including the next three times: 3^15 loads unbounded.
TEST(HostileInput, IncludeFanOutIsRefused) {
    const fs::path dir = temp_dir("fan_out");
    for (int i = 0; i < 16; ++i) {
        const std::string next = fan_out_file(i + 1);
        std::string xml = "<scene version=\"3.0.0\">\n";
        for (int k = 0; k < (i < 15 ? 3 : 0); ++k)
            xml.append("  <include filename=\"").append(next).append("\"/>\n");
        xml.append("</scene>\n");
        write_text(dir / fan_out_file(i), xml);
    }
    const auto r = reference((dir / "f0.xml").string());
    expect_one_line_error(r, "files loaded in all");
    EXPECT_NE(r.err.find(dir.string() + "/f"), std::string::npos) << r.err;
    fs::remove_all(dir);
}

// Each <default> pastes the previous one 16 times: 16^9 bytes unbounded. The line quotes only a
// prefix of the value.
TEST(HostileInput, DefaultExpansionIsRefusedInAShortLine) {
    const std::string scene = kBad + "mitsuba-default-expansion.xml";
    const auto r = reference(scene);
    expect_one_line_error(r, scene + ":");
    EXPECT_NE(r.err.find("expands past"), std::string::npos) << r.err.substr(0, 300);
    EXPECT_LT(r.err.size(), 400u);
}

// Up parallel to the view: a NaN frame, then Embree's assertion (SIGABRT), in every command that
// makes camera rays, from the first sensor or a second one chosen with --camera 1.
TEST(HostileInput, ASensorWhoseUpIsAlongItsViewIsRefused) {
    for (const std::string name :
         {"mitsuba-sensor-up-along-view.xml", "mitsuba-lookat-up-along-view.xml",
          "camera-up-along-view.gltf"}) {
        expect_one_line_error(reference(kBad + name), kBad + name);
    }
    const std::string matrix = kBad + "mitsuba-sensor-up-along-view.xml";
    expect_one_line_error(
        test::run_mvpl_gpu("render " + matrix + " --res 8x8 --vpls 4 -o /tmp/mvpl_hostile.exr",
                           kBounded),
        matrix + ":2: the sensor's up is parallel to its view direction");
    expect_one_line_error(
        test::run_mvpl_gpu("vpls " + matrix + " --view camera --res 8x8 -o /tmp/mvpl_hostile.png",
                           kBounded),
        matrix + ":2:");
    // A good first sensor and a degenerate second one.
    const fs::path dir = temp_dir("second_sensor");
    write_text(dir / "two.xml",
               "<scene version=\"3.0.0\">\n"
               "  <sensor type=\"perspective\"/>\n"
               "  <sensor type=\"perspective\">\n"
               "    <transform name=\"to_world\">\n"
               "      <matrix value=\"1 0 0 0  0 1 1 0  0 0 0 5  0 0 0 1\"/>\n"
               "    </transform>\n"
               "  </sensor>\n"
               "  <shape type=\"rectangle\"/>\n"
               "</scene>\n");
    expect_one_line_error(reference((dir / "two.xml").string(), "--camera 1"),
                          (dir / "two.xml").string() + ":3:");
    fs::remove_all(dir);
}

// open() of a FIFO waits for a writer that never comes.
TEST(HostileInput, AFifoIsRefusedNotOpened) {
    const fs::path dir = temp_dir("fifo");
    const std::string ply = (dir / "x.ply").string(), exr = (dir / "x.exr").string();
    ASSERT_EQ(::mkfifo(ply.c_str(), 0600), 0);
    ASSERT_EQ(::mkfifo(exr.c_str(), 0600), 0);
    expect_one_line_error(reference(ply), ply + ": is a FIFO");
    const std::string hdr = (dir / "sky.hdr").string();
    ASSERT_EQ(::mkfifo(hdr.c_str(), 0600), 0);
    expect_one_line_error(reference(kCbox, "--env " + hdr), hdr + ": is a FIFO");
    const std::string good = (dir / "good.exr").string();
    write_exr(Image(4, 4), good);
    expect_one_line_error(run_mvpl_env(kBounded, "compare " + exr + " " + good),
                          exr + ": is a FIFO");
    expect_one_line_error(run_mvpl_env(kBounded, "compare " + good + " " + exr),
                          exr + ": is a FIFO");
    fs::remove_all(dir);
}

TEST(HostileInput, ConvergenceOutThatCannotBeAFolderIsRefused) {
    const fs::path dir = temp_dir("convergence_out");
    const std::string ref = (dir / "ref.exr").string(), file = (dir / "file").string();
    ASSERT_EQ(run_mvpl_env(kBounded, "reference " + kCbox + " --res 8x8 --spp 1 --quiet -o " + ref)
                  .exit_code,
              0);
    write_text(file, "not a folder");
    for (const std::string& out : {file, file + "/sub"}) {
        const auto r = test::run_mvpl_gpu(
            "convergence " + kCbox + " --ref " + ref + " --no-plot --budget 1 --out " + out,
            kBounded);
        expect_one_line_error(r, out + ": cannot be a folder: '" + file + "' is a file");
    }
    fs::remove_all(dir);
}

// Usage for the newcomer on stdout, the one error line and exit code 2 for scripts.
TEST(HostileInput, BareMvplPrintsUsageToStdoutAndOneErrorLine) {
    const auto r = run_mvpl_env(kBounded, "");
    expect_one_line_error(r, "no command given (see mvpl --help)");
    EXPECT_NE(r.out.find("usage: mvpl COMMAND"), std::string::npos) << r.out;
}

TEST(HostileInput, CompareOfAnImageHoldingNanIsRefused) {
    const fs::path dir = temp_dir("nan");
    const std::string nan = (dir / "nan.exr").string(), good = (dir / "good.exr").string();
    Image image(4, 4);
    image.at(1, 2) = Rgb(std::numeric_limits<float>::quiet_NaN());
    image.at(3, 3) = Rgb(1.0f, std::numeric_limits<float>::infinity(), 0.0f);
    write_exr(image, nan);
    write_exr(Image(4, 4), good);
    expect_one_line_error(run_mvpl_env(kBounded, "compare " + nan + " " + good),
                          nan + ": holds 2 non-finite pixels");
    expect_one_line_error(run_mvpl_env(kBounded, "compare " + good + " " + nan),
                          nan + ": holds 2 non-finite pixels");
    fs::remove_all(dir);
}

// As `render` does, `reference` refuses a film that cannot fit in memory up front, with the
// estimate; here the memory is an address-space limit, which AddressSanitizer's shadow cannot live
// under.
TEST(HostileInput, ReferenceRefusesAnImageThatCannotFitUpFront) {
#if defined(__SANITIZE_ADDRESS__)
    GTEST_SKIP() << "ulimit -v and AddressSanitizer's shadow memory do not mix";
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
    GTEST_SKIP() << "ulimit -v and AddressSanitizer's shadow memory do not mix";
#endif
#endif
    const auto r = run_mvpl_env("ulimit -v 3000000; " + kBounded,
                                "reference " + kCbox + " --res 16384x16384 -o /tmp/never.exr");
    expect_one_line_error(r, "reference: a 16384x16384 image needs about");
    EXPECT_NE(r.err.find("of host memory; this machine has 3.1 GB"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace mvpl
