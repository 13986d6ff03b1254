#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <utility>

#include "engine/core/error.h"
#include "engine/core/image.h"
#include "engine/core/image_metrics.h"
#include "tests/cli/run_command.h"
#include "tools/cli/arg_parser.h"

namespace mvpl {
namespace {

using test::expect_one_line_error;

using test::run_mvpl;
using test::shell_quote;

const std::string kCbox = MVPL_ASSETS_DIR "/cornell-box/cbox.gltf";

std::string temp_file(const std::string& name) {
    return (std::filesystem::temp_directory_path() /
            ("mvpl_cli_" + std::to_string(::getpid()) + "_" + name))
        .string();
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
    expect_one_line_error(run_mvpl("preview " + kCbox + " --devices 2"), "--devices");
    expect_one_line_error(run_mvpl("render " + kCbox + " --pool -1"), "--pool");
    expect_one_line_error(run_mvpl("convergence " + kCbox + " --ref x.exr --clusters 0"),
                          "--clusters");
    expect_one_line_error(run_mvpl("render " + kCbox + " --rows 0"), "--rows");
}

TEST(Cli, ReferenceWritesExrAndPng) {
    const std::string exr = temp_file("cbox.exr"), png = temp_file("cbox.png");
    const auto r =
        run_mvpl("reference " + kCbox + " --spp 2 --res 24x16 --max-depth 3 --quiet -o " +
                 shell_quote(exr) + " -o " + shell_quote(png));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(r.out.empty());  // --quiet
    EXPECT_TRUE(r.err.empty());
    const Image image = read_exr(exr);
    EXPECT_EQ(image.width(), 24);
    EXPECT_EQ(image.height(), 16);
    EXPECT_GT(image.mean().r, 0.0f);
    EXPECT_GT(std::filesystem::file_size(png), 0u);

    // The same seed gives the same image; compare says so.
    const std::string again = temp_file("cbox2.exr");
    ASSERT_EQ(run_mvpl("reference " + kCbox + " --spp 2 --res 24x16 --max-depth 3 --quiet -o " +
                       shell_quote(again))
                  .exit_code,
              0);
    const auto cmp = run_mvpl("compare " + shell_quote(again) + " " + shell_quote(exr));
    ASSERT_EQ(cmp.exit_code, 0) << cmp.err;
    EXPECT_NE(cmp.out.find("relMSE 0\n"), std::string::npos) << cmp.out;
    const auto region =
        run_mvpl("compare " + shell_quote(again) + " " + shell_quote(exr) + " --region 4,2,8,6");
    ASSERT_EQ(region.exit_code, 0) << region.err;
    EXPECT_NE(region.out.find("relMSE 0\n"), std::string::npos) << region.out;
    // --and-ref: two identical references differ by nothing, so their noise's share is 0.
    const auto two = run_mvpl("compare " + shell_quote(again) + " " + shell_quote(exr) +
                              " --and-ref " + shell_quote(again));
    ASSERT_EQ(two.exit_code, 0) << two.err;
    EXPECT_NE(two.out.find("reference_noise 0\n"), std::string::npos) << two.out;
    EXPECT_NE(two.out.find("relMSE_vs_truth 0\n"), std::string::npos) << two.out;
    expect_one_line_error(
        run_mvpl("compare " + shell_quote(again) + " " + shell_quote(exr) + " --and-ref " +
                 shell_quote(MVPL_ASSETS_DIR "/cornell-box/ref-cbox-d6-4096.exr")),
        "differs");
    expect_one_line_error(
        run_mvpl("compare " + shell_quote(again) + " " + shell_quote(exr) + " --region 20,0,8,8"),
        "region");
    expect_one_line_error(
        run_mvpl("compare " + shell_quote(again) + " " + shell_quote(exr) + " --region 1,2,3"),
        "X,Y,W,H");
    expect_one_line_error(
        run_mvpl("compare " + shell_quote(exr) + " " +
                 shell_quote(MVPL_ASSETS_DIR "/cornell-box/ref-cbox-d6-4096.exr")),
        "differs");
    for (const auto& f : {exr, png, again})
        std::filesystem::remove(f);
}

// compare --json: the numbers of the text output, as one JSON object for scripts.
TEST(Cli, CompareJsonHoldsTheTextsNumbers) {
    const std::string a = temp_file("json_a.exr"), b = temp_file("json_b.exr");
    for (const auto& [path, seed] : {std::pair{a, "1"}, std::pair{b, "2"}}) {
        ASSERT_EQ(run_mvpl("reference " + kCbox + " --spp 2 --res 24x16 --quiet --seed " +
                           std::string(seed) + " -o " + shell_quote(path))
                      .exit_code,
                  0);
    }
    const auto text = run_mvpl("compare " + shell_quote(a) + " " + shell_quote(b));
    const auto json = run_mvpl("compare " + shell_quote(a) + " " + shell_quote(b) + " --json");
    ASSERT_EQ(text.exit_code, 0) << text.err;
    ASSERT_EQ(json.exit_code, 0) << json.err;
    const nlohmann::json j = nlohmann::json::parse(json.out);
    double rel_mse = 0.0;
    ASSERT_EQ(std::sscanf(text.out.c_str(), "relMSE %lf", &rel_mse), 1) << text.out;
    EXPECT_GT(rel_mse, 0.0);                                             // two seeds differ
    EXPECT_NEAR(j.at("relMSE").get<double>(), rel_mse, 1e-5 * rel_mse);  // text: 6 digits
    EXPECT_EQ(j.at("mean_ratio").size(), 3u);
    for (const char* key : {"RMSE", "mean_abs", "rel_err_p999", "max_ratio"})
        EXPECT_TRUE(j.contains(key)) << key;
    EXPECT_FALSE(j.contains("reference_noise"));
    const auto two = run_mvpl("compare " + shell_quote(a) + " " + shell_quote(b) + " --and-ref " +
                              shell_quote(a) + " --json");
    ASSERT_EQ(two.exit_code, 0) << two.err;
    const nlohmann::json k = nlohmann::json::parse(two.out);
    EXPECT_GT(k.at("reference_noise").get<double>(), 0.0);
    EXPECT_NEAR(k.at("relMSE_vs_truth").get<double>(),
                k.at("relMSE").get<double>() - k.at("reference_noise").get<double>(), 1e-12);
    for (const auto& f : {a, b})
        std::filesystem::remove(f);
}

TEST(Cli, SummaryLineWithoutQuiet) {
    const std::string exr = temp_file("summary.exr");
    const auto r = run_mvpl("reference " + kCbox + " --spp 1 --res 8x8 -o " + shell_quote(exr));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("Mrays/s"), std::string::npos) << r.out;
    // Not a terminal: no progress bar.
    EXPECT_TRUE(r.err.empty()) << r.err;
    std::filesystem::remove(exr);
}

// `mvpl render` on the GPU (lavapipe in CI) with the validation layers on: an image close to the
// CPU oracle's for the same VPLs, a summary line, no validation message, and one-line usage errors.
test::CommandResult run_gpu(const std::string& args) {
    return test::run_mvpl_gpu(args);
}

TEST(Cli, RenderOnTheGpuMatchesTheOracle) {
    const std::string gpu = temp_file("render_gpu.exr"), cpu = temp_file("render_cpu.exr");
    const std::string common =
        "render " + kCbox + " --vpls 16 --res 32x32 --shadow-res 64 --seed 3 ";
    const auto r = run_gpu(common + "-o " + shell_quote(gpu));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("VPL/s"), std::string::npos) << r.out;
    const auto v =
        test::run_mvpl_gpu(common + "--quiet -o " + shell_quote(gpu), "MVPL_VALIDATION=1");
    ASSERT_EQ(v.exit_code, 0) << v.err;
    EXPECT_TRUE(v.err.empty()) << v.err;  // the validation layer said nothing
    ASSERT_EQ(run_gpu(common + "--oracle --quiet -o " + shell_quote(cpu)).exit_code, 0);
    const auto cmp = run_mvpl("compare " + shell_quote(gpu) + " " + shell_quote(cpu));
    ASSERT_EQ(cmp.exit_code, 0) << cmp.err;
    const double rel_mse = std::stod(cmp.out.substr(cmp.out.find("relMSE ") + 7));
    EXPECT_LT(rel_mse,
              1.25 * 2.0 / 64.0);  // the shadow-map bound of tests/render/test_vpl_pipeline.cpp
    EXPECT_GT(read_exr(gpu).mean().r, 0.0f);
    expect_one_line_error(run_gpu("render " + kCbox + " --sampler magic"), "--sampler");
    expect_one_line_error(run_gpu("render " + kCbox + " --vpl-per-path some"), "--vpl-per-path");
    expect_one_line_error(run_gpu("render " + kCbox + " --clamp -1"), "--clamp");
    expect_one_line_error(run_gpu("render " + kCbox + " --device 99 -o " + shell_quote(gpu)),
                          "device");
    for (const auto& f : {gpu, cpu})
        std::filesystem::remove(f);
}

// --interleave's default (0): off where the scene's specular chains are traced (assets/glossy)
// or the image has fewer than 256² pixels, 2 elsewhere (the Cornell box at 256²): the default
// images equal --interleave 1 and 2 to the bit, and differ from the other K (so the test can
// fail).
TEST(Cli, InterleavingIsLeftOffWhereChainsAreTracedOrTheImageIsSmallByDefault) {
    const std::string glossy = shell_quote(std::string(MVPL_ASSETS_DIR) + "/glossy/glossy.gltf");
    const auto image = [&](const std::string& scene, const std::string& res,
                           const std::string& extra, const std::string& name) {
        const std::string out = temp_file(name);
        const auto r = run_gpu("render " + scene + " --vpls 16 --res " + res +
                               " --shadow-res 16 --seed 2 --no-compensate --no-caustics --quiet " +
                               extra + " -o " + shell_quote(out));
        EXPECT_EQ(r.exit_code, 0) << r.err;
        const Image i = read_exr(out);
        std::filesystem::remove(out);
        return i;
    };
    // The default image equals --interleave `same` to the bit and differs from --interleave
    // `other`.
    const auto expect_default = [&](const std::string& scene, const std::string& res, int same,
                                    int other) {
        SCOPED_TRACE(scene + " at " + res);
        const Image by_default = image(scene, res, "", "d.exr");
        const auto rmse_against = [&](int k) {
            const std::string flag = "--interleave " + std::to_string(k);
            return compare_images(by_default, image(scene, res, flag, "k.exr")).rmse;
        };
        EXPECT_EQ(rmse_against(same), 0.0);
        EXPECT_GT(rmse_against(other), 0.0);
    };
    expect_default(glossy, "256x256", 1, 2);
    expect_default(kCbox, "256x256", 2, 1);
    expect_default(kCbox, "255x256", 1, 2);
}

// Clamping compensation is on by default: it adds light where the clamp removed it (corners), so
// the image is brighter than with --no-compensate (measured: 0.52 %; the unclamped image of the
// same 64 paths, 0.16 %, noisy); whether the amount is right is test_clamp_compensation's
// business. The flags are checked.
TEST(Cli, RenderCompensatesTheClampByDefault) {
    const std::string on = temp_file("comp_on.exr"), off = temp_file("comp_off.exr"),
                      unclamped = temp_file("comp_unclamped.exr");
    const std::string common =
        "render " + kCbox + " --vpls 64 --res 32x32 --shadow-res 64 --seed 5 --quiet ";
    ASSERT_EQ(run_gpu(common + "--compensation-spp 64 -o " + shell_quote(on)).exit_code, 0);
    ASSERT_EQ(run_gpu(common + "--no-compensate -o " + shell_quote(off)).exit_code, 0);
    ASSERT_EQ(run_gpu(common + "--clamp 0 -o " + shell_quote(unclamped)).exit_code, 0);
    const double with = luminance(read_exr(on).mean());
    const double without = luminance(read_exr(off).mean());
    const double full = luminance(read_exr(unclamped).mean());
    EXPECT_GT(with, without * 1.001);
    EXPECT_GT(full, without);
    RecordProperty("gain", std::to_string(with / without));
    RecordProperty("unclamped_gain", std::to_string(full / without));
    expect_one_line_error(run_gpu(common + "--compensate --no-compensate"), "--no-compensate");
    expect_one_line_error(run_gpu(common + "--compensation-spp -1"), "--compensation-spp");
    for (const auto& f : {on, off, unclamped})
        std::filesystem::remove(f);
}

// A scene without any light is lit by a uniform white sky (one line says so); --no-default-light
// keeps it black with the old warning; --env-color sets the sky, which the background shows.
TEST(Cli, AnUnlitSceneGetsTheDefaultSky) {
    const std::string scene = MVPL_TEST_DATA_DIR "/gltf/flat_normals.gltf";
    const std::string lit = temp_file("sky_lit.exr"), black = temp_file("sky_black.exr"),
                      tinted = temp_file("sky_tinted.exr");
    const std::string common = "render " + shell_quote(scene) + " --vpls 16 --res 16x16 --quiet ";
    const auto r = run_gpu(common + "-o " + shell_quote(lit));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("uniform white sky"), std::string::npos) << r.err;
    EXPECT_GT(read_exr(lit).mean().g, 0.1f);
    const auto b = run_gpu(common + "--no-default-light -o " + shell_quote(black));
    ASSERT_EQ(b.exit_code, 0) << b.err;
    EXPECT_NE(b.err.find("no light"), std::string::npos) << b.err;
    EXPECT_EQ(read_exr(black).mean(), Rgb(0.0f));
    const auto t = run_gpu(common + "--env-color 0,0,2 --env-scale 0.5 -o " + shell_quote(tinted));
    ASSERT_EQ(t.exit_code, 0) << t.err;
    EXPECT_EQ(t.err.find("white sky"), std::string::npos) << t.err;
    const Rgb m = read_exr(tinted).mean();
    EXPECT_EQ(m.r, 0.0f);
    EXPECT_GT(m.b, 0.1f);
    expect_one_line_error(run_gpu(common + "--env-color 1,2"), "--env-color");
    expect_one_line_error(run_gpu(common + "--env-color 1,x,2"), "--env-color");
    expect_one_line_error(run_gpu(common + "--env-scale -1"), "--env-scale");
    expect_one_line_error(run_gpu(common + "--env /nonexistent/sky.hdr"),
                          "/nonexistent/sky.hdr: no such environment map");
    for (const auto& f : {lit, black, tinted})
        std::filesystem::remove(f);
}

// A camera inside a room with yfov 3.1 and znear 0.2 (tests/data/gltf/wide_angle.gltf): the near
// plane, where the G-buffer's rasteriser clips, cuts through most of the view. Camera rays start
// on it (scene::generate_camera_ray), so the oracle shades what the GPU shades and `reference`
// sees the same surfaces; before, both started at the eye and were 70 times brighter.
TEST(Cli, WideAngleViewIsClippedAlikeByRenderOracleAndReference) {
    const std::string scene = MVPL_TEST_DATA_DIR "/gltf/wide_angle.gltf";
    const std::string gpu = temp_file("wide_gpu.exr"), cpu = temp_file("wide_cpu.exr"),
                      ref = temp_file("wide_ref.exr");
    const std::string common =
        "render " + scene + " --vpls 16 --res 32x32 --shadow-res 64 --seed 3 --quiet ";
    ASSERT_EQ(run_gpu(common + "-o " + shell_quote(gpu)).exit_code, 0);
    ASSERT_EQ(run_gpu(common + "--oracle -o " + shell_quote(cpu)).exit_code, 0);
    ASSERT_EQ(
        run_mvpl("reference " + scene + " --spp 16 --res 32x32 --quiet -o " + shell_quote(ref))
            .exit_code,
        0);
    const auto cmp = run_mvpl("compare " + shell_quote(gpu) + " " + shell_quote(cpu));
    ASSERT_EQ(cmp.exit_code, 0) << cmp.err;
    EXPECT_LT(std::stod(cmp.out.substr(cmp.out.find("relMSE ") + 7)), 1e-3) << cmp.out;
    // VPLs and the path tracer differ (16 VPLs, clamping), but not by the clipped part.
    const float render_mean = read_exr(gpu).mean().g, reference_mean = read_exr(ref).mean().g;
    EXPECT_GT(render_mean, 0.0f);
    EXPECT_GT(reference_mean, 0.5f * render_mean);
    EXPECT_LT(reference_mean, 2.0f * render_mean);
    for (const auto& f : {gpu, cpu, ref})
        std::filesystem::remove(f);
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

// --no-chains and --no-specular-chains render the same image, and a different one from the
// chained default (assets/glossy has near-mirrors; the Cornell box, all diffuse, traces no chains
// and could not tell the flags apart).
TEST(Cli, NoChainsAndNoSpecularChainsRenderTheSameImage) {
    const std::string glossy = shell_quote(std::string(MVPL_ASSETS_DIR) + "/glossy/glossy.gltf");
    const auto render = [&](const std::string& flag, const std::string& name) {
        const std::string out = temp_file(name);
        const auto r = run_gpu("render " + glossy + " --res 32x32 --vpls 16 --quiet " + flag +
                               " -o " + shell_quote(out));
        EXPECT_EQ(r.exit_code, 0) << r.err;
        return out;
    };
    const std::string old_name = render("--no-chains", "old.exr");
    const std::string new_name = render("--no-specular-chains", "new.exr");
    const std::string chained = render("", "chained.exr");
    // The pixels, not the files: the header holds each run's command line and time.
    const auto pixels = [](const std::string& path) { return read_exr(path).pixels(); };
    EXPECT_FALSE(pixels(old_name).empty());
    EXPECT_EQ(pixels(old_name), pixels(new_name));
    EXPECT_NE(pixels(old_name), pixels(chained));
    for (const auto& f : {old_name, new_name, chained})
        std::filesystem::remove(f);
}

}  // namespace
}  // namespace mvpl
