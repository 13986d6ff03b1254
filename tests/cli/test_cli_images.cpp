// What render, reference and compare write: images against the CPU oracle, the defaults'
// effect on them (interleaving, clamp compensation, the default sky, the specular chains' flags),
// compare's JSON and render's summary line. The command line itself: test_cli.cpp.
#include <gtest/gtest.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <utility>

#include "engine/core/image.h"
#include "engine/core/image_metrics.h"
#include "tests/cli/run_command.h"

namespace mvpl {
namespace {

using test::expect_one_line_error;

using test::run_mvpl;
using test::shell_quote;

const std::string kCbox = MVPL_ASSETS_DIR "/cornell-box/cbox.gltf";

std::string temp_file(const std::string& name) {
    return test::temp_file("mvpl_cli", name);
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
    // An image twice the reference's size is compared by its 2×2 means: each pixel of `exr`
    // repeated 2×2 is `exr` again, and one pixel of each 2×2 doubled moves the mean by half.
    Image twice(2 * image.width(), 2 * image.height());
    for (int y = 0; y < twice.height(); ++y)
        for (int x = 0; x < twice.width(); ++x)
            twice.at(x, y) = image.at(x / 2, y / 2);
    const std::string big = temp_file("cbox-twice.exr");
    write_exr(twice, big);
    const auto scaled = run_mvpl("compare " + shell_quote(big) + " " + shell_quote(exr));
    ASSERT_EQ(scaled.exit_code, 0) << scaled.err;
    EXPECT_NE(scaled.out.find("relMSE 0\n"), std::string::npos) << scaled.out;
    EXPECT_NE(scaled.err.find("2×2 means"), std::string::npos) << scaled.err;
    for (int y = 0; y < twice.height(); y += 2)
        for (int x = 0; x < twice.width(); x += 2)
            twice.at(x, y) *= 2.0f;
    write_exr(twice, big);
    const auto brighter = run_mvpl("compare " + shell_quote(big) + " " + shell_quote(exr));
    ASSERT_EQ(brighter.exit_code, 0) << brighter.err;
    EXPECT_NE(brighter.out.find("mean_ratio 1.25"), std::string::npos) << brighter.out;
    const Image odd(2 * image.width() + 1, 2 * image.height());
    write_exr(odd, big);
    expect_one_line_error(run_mvpl("compare " + shell_quote(big) + " " + shell_quote(exr)),
                          "differs");
    for (const auto& f : {exr, png, again, big})
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
