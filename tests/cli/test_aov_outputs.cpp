// --aov and the EXR attributes on the command line (README, "AOVs", "EXR attributes"): the
// channels under the compositors' names, the run's attributes read back with OpenEXR, a Mitsuba
// scene's aov integrator written under its own names, and a bad name refused in one line.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "engine/core/exr_file.h"
#include "engine/core/version.h"
#include "tests/cli/run_command.h"

namespace mvpl {
namespace {

namespace fs = std::filesystem;
using test::expect_one_line_error;
using test::shell_quote;

const std::string kCbox = MVPL_ASSETS_DIR "/cornell-box/cbox.gltf";

fs::path temp_file(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("mvpl_aov_cli_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir / name;
}

std::set<std::string> channel_names(const ExrContents& exr) {
    std::set<std::string> names;
    for (const auto& c : exr.channels)
        names.insert(c.first);
    return names;
}

TEST(AovCli, RenderWritesTheAovChannelsAndTheRunsAttributes) {
    const fs::path out = temp_file("render.exr");
    const std::string args = kCbox + " --vpls 32 --res 12x12 --seed 7 --aov " +
                             "albedo,normal,depth,position -o " + out.string();  // no quotes needed
    const test::CommandResult r = test::run_mvpl_gpu("render " + args);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const ExrContents exr = read_exr_file(out.string());
    EXPECT_EQ(channel_names(exr),
              (std::set<std::string>{"R", "G", "B", "albedo.R", "albedo.G", "albedo.B", "N.X",
                                     "N.Y", "N.Z", "Z", "P.X", "P.Y", "P.Z"}));
    // A mean of unit normals, of depths (0 where nothing is hit) and of albedos in [0, 1].
    const std::vector<float>& z = *exr.channel("Z");
    EXPECT_GT(z[6 * 12 + 6], 0.0f);  // the box's back wall
    for (size_t i = 0; i < z.size(); ++i) {
        const float n = std::hypot((*exr.channel("N.X"))[i], (*exr.channel("N.Y"))[i],
                                   (*exr.channel("N.Z"))[i]);
        EXPECT_GE(z[i], 0.0f) << i;
        EXPECT_LE(n, 1.0f + 1e-5f) << i;
        EXPECT_LE((*exr.channel("albedo.G"))[i], 1.0f) << i;
    }
    EXPECT_EQ(exr.attribute("mvpl/version"), version());
    EXPECT_EQ(exr.attribute("mvpl/commandLine"), "mvpl render " + args);
    EXPECT_EQ(exr.attribute("mvpl/seed"), "7");
    // The VPL count the summary line gives.
    std::smatch m;
    ASSERT_TRUE(std::regex_search(r.out, m, std::regex("render: (\\d+) VPLs"))) << r.out;
    EXPECT_EQ(exr.attribute("mvpl/vpls"), m[1].str());
    EXPECT_GT(std::atof(exr.attribute("mvpl/wallSeconds").c_str()), 0.0);
    EXPECT_TRUE(exr.has_attribute("chromaticities"));
    fs::remove(out);
}

TEST(AovCli, ReferenceWritesItsAovsAndSamples) {
    const fs::path out = temp_file("reference.exr");
    const test::CommandResult r =
        test::run_mvpl("reference " + kCbox + " --spp 2 --res 8x8 --quiet --aov depth,albedo -o " +
                       shell_quote(out.string()));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const ExrContents exr = read_exr_file(out.string());
    EXPECT_EQ(channel_names(exr),
              (std::set<std::string>{"R", "G", "B", "Z", "albedo.R", "albedo.G", "albedo.B"}));
    EXPECT_EQ(exr.attribute("mvpl/spp"), "2");
    EXPECT_EQ(exr.attribute("mvpl/seed"), "0");
    EXPECT_FALSE(exr.has_attribute("mvpl/vpls"));
    fs::remove(out);
}

// tests/data/mitsuba/cbox.xml with its path integrator inside Mitsuba 3's aov integrator.
TEST(AovCli, AMitsubaAovIntegratorIsWrittenUnderItsNames) {
    std::ifstream in(MVPL_TEST_DATA_DIR "/mitsuba/cbox.xml");
    std::stringstream text;
    text << in.rdbuf();
    std::string xml = text.str();
    const std::string from = "<integrator type=\"path\">";
    ASSERT_NE(xml.find(from), std::string::npos);
    xml.replace(xml.find(from), from.size(),
                "<integrator type=\"aov\"><string name=\"aovs\" value=\"dd.y:depth,nn:sh_normal\"/>"
                "<integrator type=\"path\">");
    xml.replace(xml.find("</integrator>"), 13, "</integrator></integrator>");
    const fs::path scene = temp_file("cbox_aov.xml");
    std::ofstream(scene) << xml;
    const fs::path out = temp_file("mitsuba.exr");
    test::CommandResult r =
        test::run_mvpl("reference " + shell_quote(scene.string()) +
                       " --spp 1 --res 8x8 --quiet -o " + shell_quote(out.string()));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(channel_names(read_exr_file(out.string())),
              (std::set<std::string>{"R", "G", "B", "dd.y.T", "nn.X", "nn.Y", "nn.Z"}));
    // --aov replaces the file's list.
    r = test::run_mvpl("reference " + shell_quote(scene.string()) +
                       " --spp 1 --res 8x8 --quiet --aov position -o " + shell_quote(out.string()));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(channel_names(read_exr_file(out.string())),
              (std::set<std::string>{"R", "G", "B", "P.X", "P.Y", "P.Z"}));
    fs::remove(out);
    fs::remove(scene);
}

TEST(AovCli, ABadAovIsRefusedInOneLine) {
    expect_one_line_error(test::run_mvpl("render " + kCbox + " --aov albedo,colour"),
                          "render: --aov: unknown AOV 'colour' (albedo, normal, depth, position)");
    expect_one_line_error(test::run_mvpl("reference " + kCbox + " --aov depth,depth"),
                          "reference: --aov: AOV 'depth' given twice");
    expect_one_line_error(test::run_mvpl("reference " + kCbox + " --aov depth -o x.png"),
                          "reference: --aov writes EXR channels");
}

}  // namespace
}  // namespace mvpl
