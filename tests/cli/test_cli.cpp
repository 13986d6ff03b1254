// mvpl's command line itself: usage errors and refused input (one line, exit 2), every
// command's --help and completion, aliases. What the rendering commands write:
// test_cli_images.cpp.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <utility>

#include "engine/core/error.h"
#include "tests/cli/run_command.h"
#include "tools/cli/arg_parser.h"

namespace mvpl {
namespace {

using test::expect_one_line_error;

using test::run_mvpl;
using test::shell_quote;

const std::string kCbox = MVPL_ASSETS_DIR "/cornell-box/cbox.gltf";

std::string temp_file(const std::string& name) {
    return test::temp_file("mvpl_cli", name);
}

TEST(Cli, UsageErrors) {
    EXPECT_EQ(run_mvpl("").exit_code, 2);
    expect_one_line_error(run_mvpl("frobnicate"), "unknown command");
    expect_one_line_error(run_mvpl("reference"), "missing SCENE");
    expect_one_line_error(run_mvpl("reference " + kCbox + " --bogus"), "--bogus");
    expect_one_line_error(run_mvpl("reference " + kCbox + " --res 0x5"), "--res");
    expect_one_line_error(run_mvpl("reference " + kCbox + " --res 12"), "--res");
    expect_one_line_error(run_mvpl("reference " + kCbox + " --spp abc"), "--spp");
    expect_one_line_error(run_mvpl("reference " + kCbox + " --spp"), "needs a value");
    expect_one_line_error(run_mvpl("reference " + kCbox + " -o out.bmp"), "out.bmp");
    expect_one_line_error(run_mvpl("reference /nonexistent/scene.gltf"), "/nonexistent/scene.gltf");
    const auto help = run_mvpl("reference --help");
    EXPECT_EQ(help.exit_code, 0);
    EXPECT_NE(help.out.find("--max-depth"), std::string::npos);
}

// Values that used to be taken as something else (issue 19): a negative depth other than -1 as
// unlimited, 0 as 1, device -2 as the default, a repeated option as its last value.
TEST(Cli, OutOfRangeAndRepeatedOptionsAreRefused) {
    expect_one_line_error(run_mvpl("reference " + kCbox + " --max-depth -5"), "--max-depth");
    expect_one_line_error(run_mvpl("reference " + kCbox + " --max-depth 0"), "--max-depth");
    expect_one_line_error(run_mvpl("render " + kCbox + " --device -2"), "--device");
    expect_one_line_error(run_mvpl("info --device -2"), "--device");
    expect_one_line_error(run_mvpl("reference " + kCbox + " --spp 2 --spp 3"), "--spp given twice");
    expect_one_line_error(run_mvpl("render " + kCbox + " --quiet --quiet"), "--quiet given twice");
    expect_one_line_error(run_mvpl("render " + kCbox + " --specular-chain-samples 0"),
                          "--specular-chain-samples");
    expect_one_line_error(run_mvpl("render " + kCbox + " --chain-samples 65"),
                          "--specular-chain-samples");
    expect_one_line_error(run_mvpl("render " + kCbox + " --interleave -1"), "--interleave");
    expect_one_line_error(run_mvpl("render " + kCbox + " --interleave 9"), "--interleave");
    expect_one_line_error(run_mvpl("render " + kCbox + " --batches-per-position -1"),
                          "--batches-per-position");
    expect_one_line_error(run_mvpl("render " + kCbox + " --devices 9"), "--devices");
    expect_one_line_error(run_mvpl("bench " + kCbox + " --devices -1"), "--devices");
    expect_one_line_error(run_mvpl("preview " + kCbox + " --devices 9"), "--devices");
    expect_one_line_error(run_mvpl("render " + kCbox + " --pool -1"), "--pool");
    expect_one_line_error(run_mvpl("convergence " + kCbox + " --ref x.exr --clusters -1"),
                          "--clusters");
    expect_one_line_error(run_mvpl("render " + kCbox + " --rows 0"), "--rows");
    expect_one_line_error(run_mvpl("render " + kCbox + " --matrix fpga"), "--matrix");
    expect_one_line_error(run_mvpl("bench " + kCbox + " --row-resolution 2"), "--row-resolution");
}

// Scene values beyond engine/scene/scene_range.h (issue 19): every command that loads a scene
// refuses them before any work, with one line naming the file, the JSON path and the value —
// `render` used to fail on an `inf` in generated GLSL (exit 1), `reference` to abort inside
// Embree (exit 134) or write a black image (exit 0).
TEST(Cli, SceneValuesBeyondTheRepresentableRangeAreRefusedByEveryCommand) {
    const std::string bad = MVPL_TEST_DATA_DIR "/bad/";
    const std::pair<std::string, std::string> cases[] = {
        {"emissive-factor-beyond-range.gltf", "materials[0].emissiveFactor[0] is 1e+308"},
        {"texture-transform-scale-beyond-range.gltf", "KHR_texture_transform.scale[0] is 1e+308"},
        {"light-intensity-beyond-range.gltf", "lights[0].intensity is 1e+38"},
        {"random-bytes-positions.gltf", "beyond the supported magnitude 1e+09"},
        {"directional-light-power-beyond-range.gltf", "more than the supported 1e+22 W"},
        {"camera-yfov-tiny.gltf", "cameras[0].perspective.yfov is 1e-30"},
        {"draco-required-before-accessor-error.gltf",
         "required extension KHR_draco_mesh_compression is not supported"},
    };
    const std::string out = shell_quote(temp_file("range.png"));
    const std::string commands[] = {
        "render {} --vpls 16 --res 8x8 --quiet -o " + out,
        "reference {} --spp 1 --res 8x8 --quiet -o " + out,
        "vpls {} --vpls 16 -o " + out,
    };
    for (const auto& [file, reason] : cases) {
        for (std::string command : commands) {
            command.replace(command.find("{}"), 2, shell_quote(bad + file));
            SCOPED_TRACE(command);
            const auto r = run_mvpl(command);
            expect_one_line_error(r, bad + file);
            expect_one_line_error(r, reason);
        }
    }
    EXPECT_FALSE(std::filesystem::exists(temp_file("range.png")));
}

// Every file of the bad-input corpus: exit code 2 and one line naming the file, never a crash.
TEST(Cli, BadInputCorpus) {
    const std::filesystem::path dir = MVPL_TEST_DATA_DIR "/bad";
    ASSERT_TRUE(std::filesystem::is_directory(dir));
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        if (!entry.is_regular_file()) continue;
        const std::string ext = entry.path().extension().string();
        if (ext == ".bin" || ext == ".png" || ext == ".md" || ext == ".py") continue;  // companions
        ++files;
        const std::string path = entry.path().string();
        SCOPED_TRACE(path);
        const auto r =
            run_mvpl("reference " + shell_quote(path) + " --spp 1 --res 4x4 --quiet -o " +
                     shell_quote(temp_file("bad.exr")));
        expect_one_line_error(r, path);
    }
    EXPECT_GE(files, 20);
}

// Each command's --help: exit 0, nothing on stderr, its usage line, and a value name for every
// option that takes one (never the old placeholder VALUE).
TEST(Cli, EveryCommandsHelpExitsZero) {
    for (const std::string command : {"render", "reference", "compare", "info", "preview", "vpls",
                                      "bench", "convergence", "completion"}) {
        for (const std::string flag : {" --help", " -h"}) {
            SCOPED_TRACE(command + flag);
            const auto r = run_mvpl(command + flag);
            EXPECT_EQ(r.exit_code, 0);
            EXPECT_TRUE(r.err.empty()) << r.err;
            EXPECT_EQ(r.out.rfind("usage: mvpl " + command, 0), 0u) << r.out;
            EXPECT_EQ(r.out.find(" VALUE"), std::string::npos) << r.out;
        }
    }
    const auto top = run_mvpl("--help");
    EXPECT_EQ(top.exit_code, 0);
    EXPECT_NE(top.out.find("commands:"), std::string::npos);
}

// `mvpl completion` (issue 34): bash only; its script lists every command.
TEST(Cli, CompletionIsForBash) {
    expect_one_line_error(run_mvpl("completion zsh"), "completion: SHELL must be bash, not 'zsh'");
    const auto r = run_mvpl("completion bash");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    for (const std::string command :
         {"render", "reference", "compare", "info", "preview", "vpls", "bench", "convergence"})
        EXPECT_NE(r.out.find("    " + command + ")\n"), std::string::npos) << command;
}

// `mvpl render --help`: the options under their groups' headings, in the order the command
// declares the groups, with value names, the specular chains' old names as aliases and the
// Metropolis chains named as such.
TEST(Cli, RenderHelpIsGroupedWithValueNames) {
    const auto r = run_mvpl("render --help");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string& help = r.out;
    size_t at = 0;
    for (const char* heading :
         {"Arguments:", "Render options:", "Sampler:", "Metropolis sampler:", "GPU renderer:",
          "Specular chains:", "Clamping compensation:", "Caustics:", "Path depth:", "Seed:",
          "Camera:", "Environment:", "Mitsuba scene file:", "Device:", "Examples:"}) {
        const size_t found = help.find(std::string("\n") + heading + "\n");
        ASSERT_NE(found, std::string::npos) << heading << " missing:\n" << help;
        EXPECT_GT(found, at) << heading << " out of order";
        at = found;
    }
    for (const char* line :
         {"\n  --time-budget SEC\n", "\n  --res WxH\n", "\n  -o FILE\n", "\n  --dump-shaders DIR\n",
          "\n  --sampler mc|metropolis\n", "\n  --vpls N\n", "\n  --clamp X\n",
          "\n  --no-specular-chains (alias: --no-chains)\n",
          "\n  --specular-chain-roughness X (alias: --chain-roughness)\n",
          "\n  --specular-chain-samples N (alias: --chain-samples)\n"}) {
        EXPECT_NE(help.find(line), std::string::npos) << line;
    }
    EXPECT_EQ(help.find(" VALUE"), std::string::npos);
    const size_t chains = help.find("\n  --chains N\n");
    ASSERT_NE(chains, std::string::npos);
    EXPECT_NE(help.find("Metropolis chains", chains), std::string::npos);
    // Every option line sits under a heading: a blank line never precedes one.
    EXPECT_EQ(help.find("\n\n  -"), std::string::npos);
}

// The examples at the end of render, convergence, bench and preview --help name files that exist.
TEST(Cli, HelpExamplesNameFilesThatExist) {
    const std::filesystem::path root = std::filesystem::path(MVPL_ASSETS_DIR).parent_path();
    for (const std::string command : {"render", "convergence", "bench", "preview"}) {
        SCOPED_TRACE(command);
        const auto r = run_mvpl(command + " --help");
        const size_t examples = r.out.find("\nExamples:\n");
        ASSERT_NE(examples, std::string::npos);
        std::istringstream words(r.out.substr(examples));
        int files = 0, lines = 0;
        for (std::string word; words >> word;) {
            if (word == "mvpl") ++lines;
            if (word.rfind("assets/", 0) != 0 && word.rfind("docs/", 0) != 0) continue;
            ++files;
            EXPECT_TRUE(std::filesystem::exists(root / word)) << word;
        }
        EXPECT_GE(lines, 2);
        EXPECT_GE(files, lines);
    }
}

// An alias is the option it names: given with it, the option is given twice (one line, exit 2),
// and an out-of-range value through it is reported under the option's name.
TEST(Cli, AnAliasAndItsOptionAreGivenTwice) {
    const std::string pairs[][2] = {{"--no-chains", "--no-specular-chains"},
                                    {"--chain-samples 4", "--specular-chain-samples 4"},
                                    {"--chain-roughness=0.1", "--specular-chain-roughness 0.1"}};
    for (const auto& [alias, name] : pairs) {
        expect_one_line_error(run_mvpl("render " + kCbox + " " + alias + " " + name),
                              "given twice");
        expect_one_line_error(run_mvpl("render " + kCbox + " " + name + " " + alias),
                              "given twice");
    }
    expect_one_line_error(run_mvpl("render " + kCbox + " --chain-roughness 2"),
                          "--specular-chain-roughness must be in [0, 1]");
    // The Metropolis chains are not an alias of anything.
    expect_one_line_error(run_mvpl("render " + kCbox + " --chains 4 --no-chains --chains 8"),
                          "--chains given twice");
}

// ArgParser::given answers for an option by its name and by its alias alike.
TEST(Cli, ArgParserGivenCountsAnAliasAsItsOption) {
    bool no_chains = false;
    int samples = 8;
    cli::ArgParser parser("test", "");
    parser.add_flag("--no-specular-chains", &no_chains, "");
    parser.add_alias("--no-chains", "--no-specular-chains");
    parser.add_int("--specular-chain-samples", &samples, "");
    parser.add_alias("--chain-samples", "--specular-chain-samples");
    ASSERT_TRUE(parser.parse({"--no-chains", "--specular-chain-samples", "3"}));
    EXPECT_TRUE(no_chains);
    EXPECT_EQ(samples, 3);
    for (const char* name :
         {"--no-chains", "--no-specular-chains", "--chain-samples", "--specular-chain-samples"})
        EXPECT_TRUE(parser.given(name)) << name;
    ASSERT_TRUE(parser.parse({"--chain-samples=5"}));
    EXPECT_FALSE(parser.given("--no-chains"));
    EXPECT_FALSE(parser.given("--no-specular-chains"));
    EXPECT_TRUE(parser.given("--specular-chain-samples"));
    EXPECT_THROW(parser.parse({"--no-chains", "--no-specular-chains"}), UsageError);
}

}  // namespace
}  // namespace mvpl
