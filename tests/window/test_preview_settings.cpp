// The preview's live settings driven by a script (issue 35): each changes the picture as the same
// option of `mvpl render` does, with the same VPLs (same seed), so the window's radiance (its
// .exr screenshot, after the last frame waited for the passes the render runs) equals the
// render's within the summation bound of preview_run.h; a dropped file replaces the scene or the
// environment, a bad one is reported and changes nothing. Tiny images and 64 light paths: each
// run takes about a second on lavapipe.
#include <gtest/gtest.h>
#include <stb_image.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "engine/core/exr_file.h"
#include "engine/core/image.h"
#include "tests/window/preview_run.h"
#include "tools/session/heat_colour.h"
#include "tools/session/vpl_dots.h"

namespace mvpl {
namespace {

namespace fs = std::filesystem;
using test::CommandResult;
using test::shell_quote;

const std::string kCbox = std::string(MVPL_ASSETS_DIR) + "/cornell-box/cbox.gltf";
const std::string kBox = std::string(MVPL_TEST_DATA_DIR) + "/gltf/box.glb";
// 64 light paths, 16 a frame: a setting changed at frame 2 restarts at the motion resolution,
// frame 3 at full size, and 4 frames shade the 64 paths again; 10 frames leave a margin.
const std::string kCommon = " --res 48x48 --vpls 64 --seed 5";
const std::string kFrames = " --paths-per-frame 16 --frames 10 --quiet";

fs::path temp(const std::string& name) {
    return test::preview_temp_dir() / name;
}

fs::path write_script(const std::string& name, const std::string& text) {
    const fs::path path = temp(name);
    std::ofstream(path) << text;
    return path;
}

// The preview's radiance after `script`: exit 0, and no error on stderr unless `err` takes it
// (warnings are the scene's: box.glb has no light and gets the default sky, saying so).
Image preview(const std::string& scene, const std::string& script_text, const std::string& name,
              std::string* err = nullptr, const std::string& extra = {}) {
    const fs::path script = write_script(name + ".txt", script_text);
    const fs::path exr = temp(name + ".exr");
    const CommandResult r = test::run_preview(shell_quote(scene) + kCommon + kFrames + extra +
                                              " --script " + shell_quote(script.string()) +
                                              " --screenshot " + shell_quote(exr.string()));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    if (err)
        *err = r.err;
    else
        EXPECT_EQ(r.err.find("error"), std::string::npos) << r.err;
    return r.exit_code == 0 ? read_exr(exr.string()) : Image();
}

Image render(const std::string& scene, const std::string& flags, const std::string& name) {
    const fs::path exr = temp(name + ".exr");
    const CommandResult r = test::run_mvpl_gpu("render " + shell_quote(scene) + kCommon + " " +
                                               flags + " --quiet -o " + shell_quote(exr.string()));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return r.exit_code == 0 ? read_exr(exr.string()) : Image();
}

// IEC 61966-2-1's encoding, written out here apart from engine/core/image.cpp.
int srgb_byte(double v) {
    v = std::clamp(v, 0.0, 1.0);
    const double e = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
    return int(std::lround(255.0 * e));
}

// Exposure never restarts the sum: an exposure set halfway leaves the radiance as it was to the
// bit (a restart would have shaded fewer VPLs by the last frame: light paths are unlimited here),
// and the PNG is that radiance times 2^1.5, sRGB-encoded (within one step of 255: the GPU's
// pow() is not libm's, as in test_preview.cpp). P at the last frame writes both; without the CPU
// estimators (whose passes so far depend on the clock) the .exr is the VPLs' sum alone.
TEST(PreviewSettings, ExposureScalesThePictureWithoutRestarting) {
    if (!test::have_xvfb()) GTEST_SKIP() << "xvfb-run is not installed (apt install xvfb)";
    const auto run = [&](const std::string& script_text, const std::string& name) {
        const fs::path folder = temp(name);
        fs::remove_all(folder);
        fs::create_directories(folder);
        const fs::path script = write_script(name + ".txt", script_text + "7 key p\n");
        const CommandResult r = test::run_preview(
            shell_quote(kCbox) + " --res 48x48 --seed 5 --paths-per-frame 4 --frames 8 --quiet" +
                " --no-compensate --no-caustics --script " + shell_quote(script.string()),
            folder.string());
        EXPECT_EQ(r.exit_code, 0) << r.err;
        return folder / "cbox-0001";
    };
    const fs::path exposed_shot = run("4 set exposure 1.5\n", "exposed");
    const fs::path plain_shot = run("", "plain");
    const Image exposed = read_exr(exposed_shot.string() + ".exr");
    const Image plain = read_exr(plain_shot.string() + ".exr");
    ASSERT_EQ(exposed.pixels().size(), plain.pixels().size());
    EXPECT_EQ(exposed.pixels(), plain.pixels());
    int w = 0, h = 0, n = 0;
    unsigned char* png = stbi_load((exposed_shot.string() + ".png").c_str(), &w, &h, &n, 3);
    ASSERT_NE(png, nullptr);
    ASSERT_EQ(w, exposed.width());
    ASSERT_EQ(h, exposed.height());
    int worst = 0;
    size_t bright = 0;
    for (size_t i = 0; i < exposed.pixels().size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            const int expected = srgb_byte(std::exp2(1.5) * exposed.pixels()[i][c]);
            worst = std::max(worst, std::abs(int(png[3 * i + size_t(c)]) - expected));
            bright += expected > srgb_byte(exposed.pixels()[i][c]);
        }
    }
    stbi_image_free(png);
    EXPECT_LE(worst, 1);
    EXPECT_GT(bright, exposed.pixels().size());  // the exposure did brighten it
}

// max_depth 2 (light reaches the camera after at most one bounce) draws the VPLs anew: the
// picture is `render --max-depth 2`'s, in which what the ceiling light cannot see directly (the
// ceiling around it, the boxes' shadows) is black, while indirect light reaches all of it in
// the default's.
TEST(PreviewSettings, MaxDepthDrawsTheVplsOfThatDepth) {
    if (!test::have_xvfb()) GTEST_SKIP() << "xvfb-run is not installed (apt install xvfb)";
    const Image window = preview(kCbox, "2 set max_depth 2\n", "depth");
    const Image direct = render(kCbox, "--max-depth 2", "depth_render");
    size_t lit = 0;
    EXPECT_EQ(test::channels_differing(window, direct, &lit), 0u);
    EXPECT_GT(lit, direct.pixels().size());
    const auto black = [](const Image& image) {
        return std::count_if(image.pixels().begin(), image.pixels().end(),
                             [](const Rgb& p) { return p[0] + p[1] + p[2] == 0.0f; });
    };
    const Image full = render(kCbox, "", "full_render");
    // Measured: 834 black pixels of 2304 at depth 2, 139 at the default depth (where 64 light
    // paths leave some corners unlit); a tenth of the picture separates the two with margin.
    EXPECT_GT(size_t(black(window)), size_t(black(full)) + window.pixels().size() / 10);
}

// A scene dropped on the window replaces it (here the Cornell box with a second camera node);
// `camera 1` then frames it as `render --camera 1` does and `fov` sets the field of view.
TEST(PreviewSettings, DroppedSceneAndItsCameraNAreTheRendersView) {
    if (!test::have_xvfb()) GTEST_SKIP() << "xvfb-run is not installed (apt install xvfb)";
    std::ifstream in(kCbox);
    nlohmann::json doc = nlohmann::json::parse(in);
    doc["nodes"].push_back(
        {{"camera", 0}, {"translation", {150, 350, -600}}, {"rotation", {0, 1, 0, 0}}});
    doc["scenes"][0]["nodes"].push_back(doc["nodes"].size() - 1);
    const fs::path scene = temp("two_cameras.gltf");
    std::ofstream(scene) << doc.dump();
    fs::copy_file(fs::path(kCbox).parent_path() / "cbox.bin", temp("cbox.bin"),
                  fs::copy_options::overwrite_existing);
    const Image window =
        preview(kBox, "1 drop " + scene.string() + "\n2 camera 1\n2 fov 30\n", "camera");
    const Image second = render(scene.string(), "--camera 1 --fov 30", "camera_render");
    size_t lit = 0;
    EXPECT_EQ(test::channels_differing(window, second, &lit), 0u);
    EXPECT_GT(lit, second.pixels().size());
    const Image first = render(scene.string(), "--fov 30", "camera0_render");
    EXPECT_GT(test::channels_differing(window, first), window.pixels().size());
}

// An environment map dropped on the window replaces the sky, and env_scale scales it (`render
// --env FILE --env-scale 2`'s picture); a bad scene dropped after it is reported in one line and
// keeps all as it was; the run exits 0.
TEST(PreviewSettings, DroppedEnvironmentReplacesTheSkyAndABadFileKeepsTheScene) {
    if (!test::have_xvfb()) GTEST_SKIP() << "xvfb-run is not installed (apt install xvfb)";
    Image map(16, 8);
    for (int y = 0; y < map.height(); ++y)
        for (int x = 0; x < map.width(); ++x)
            map.at(x, y) = Rgb(0.2f + 0.1f * float(x), 0.5f, 2.0f - 0.2f * float(y));
    const fs::path env = temp("sky.exr");
    write_exr(map, env.string());
    const std::string bad = std::string(MVPL_TEST_DATA_DIR) + "/bad/empty.gltf";
    std::string err;
    const Image window = preview(
        kBox, "1 drop " + env.string() + "\n2 set env_scale 2\n3 drop " + bad + "\n", "env", &err);
    // One line: the error, beside the scene's warning about its light.
    const size_t error = err.find("mvpl: error: ");
    ASSERT_NE(error, std::string::npos) << err;
    EXPECT_EQ(err.substr(error).rfind("mvpl: error: " + bad + ": ", 0), 0u) << err;
    EXPECT_EQ(std::count(err.begin() + long(error), err.end(), '\n'), 1) << err;
    EXPECT_EQ(err.find("error", error + 13), std::string::npos) << err;
    const Image sky =
        render(kBox, "--env " + shell_quote(env.string()) + " --env-scale 2", "env_render");
    size_t lit = 0;
    EXPECT_EQ(test::channels_differing(window, sky, &lit), 0u);
    EXPECT_GT(lit, sky.pixels().size());
    const Image white = render(kBox, "", "white_render");
    EXPECT_GT(test::channels_differing(window, white), window.pixels().size());
}

// `view albedo` shows (and an .exr screenshot holds) `render --aov albedo`'s AOV over the same
// sub-pixel positions: 16 light paths leave 55 VPLs, two positions, within the four a view
// follows. The same tracer on both sides: equal to float rounding of the same sums.
TEST(PreviewSettings, AlbedoViewIsTheRendersAov) {
    if (!test::have_xvfb()) GTEST_SKIP() << "xvfb-run is not installed (apt install xvfb)";
    const fs::path script = write_script("view.txt", "1 view albedo\n");
    const fs::path exr = temp("view.exr");
    const std::string common = shell_quote(kCbox) + " --res 48x48 --vpls 16 --seed 5";
    const CommandResult r = test::run_preview(common + " --paths-per-frame 16 --frames 6 --quiet" +
                                              " --script " + shell_quote(script.string()) +
                                              " --screenshot " + shell_quote(exr.string()));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const fs::path aov = temp("aov.exr");
    const CommandResult rr = test::run_mvpl_gpu("render " + common + " --aov albedo --quiet -o " +
                                                shell_quote(aov.string()));
    ASSERT_EQ(rr.exit_code, 0) << rr.err;
    const Image view = read_exr(exr.string());
    const ExrContents render = read_exr_file(aov.string());
    ASSERT_EQ(view.width(), render.width);
    ASSERT_EQ(view.height(), render.height);
    size_t bad = 0, unlike_radiance = 0;
    const char* names[3] = {"albedo.R", "albedo.G", "albedo.B"};
    const char* beauty[3] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c) {
        const std::vector<float>* albedo = render.channel(names[c]);
        const std::vector<float>* radiance = render.channel(beauty[c]);
        ASSERT_TRUE(albedo && radiance) << names[c];
        for (size_t i = 0; i < view.pixels().size(); ++i) {
            bad += std::abs(view.pixels()[i][c] - (*albedo)[i]) > 1e-6f;
            unlike_radiance += std::abs(view.pixels()[i][c] - (*radiance)[i]) > 1e-3f;
        }
    }
    EXPECT_EQ(bad, 0u);
    EXPECT_GT(unlike_radiance, view.pixels().size());  // a view, not the picture
}

// `view vpls` draws the sum's VPLs over the picture as `mvpl vpls --view camera` draws the same
// VPLs (16 light paths, same seed) over its flat view: the same pixels carry the dots' colours.
TEST(PreviewSettings, VplViewDrawsTheVplsWhereMvplVplsDoes) {
    if (!test::have_xvfb()) GTEST_SKIP() << "xvfb-run is not installed (apt install xvfb)";
    const fs::path script = write_script("vpls.txt", "1 view vpls\n");
    const fs::path exr = temp("vpls_view.exr");
    const std::string common = shell_quote(kCbox) + " --res 48x48 --vpls 16 --seed 5";
    const CommandResult r = test::run_preview(common + " --paths-per-frame 16 --frames 4 --quiet" +
                                              " --script " + shell_quote(script.string()) +
                                              " --screenshot " + shell_quote(exr.string()));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const fs::path dots = temp("vpls_command.exr");
    const CommandResult v = test::run_mvpl("vpls " + common + " --view camera --quiet -o " +
                                           shell_quote(dots.string()));
    ASSERT_EQ(v.exit_code, 0) << v.err;
    const Image a = read_exr(exr.string());
    const Image b = read_exr(dots.string());
    ASSERT_EQ(a.pixels().size(), b.pixels().size());
    // A dot's pixel is a colour of the ramp (session::heat_colour) or an emitter's white ring; a
    // radiance pixel is none of them.
    const auto dot = [](const Rgb& p) {
        return session::on_heat_ramp(p) || p == session::kEmitterRing;
    };
    size_t dotted = 0, unlike = 0;
    for (size_t i = 0; i < a.pixels().size(); ++i) {
        dotted += dot(b.pixels()[i]);
        unlike += dot(b.pixels()[i]) ? !(a.pixels()[i] == b.pixels()[i]) : dot(a.pixels()[i]);
    }
    EXPECT_GT(dotted, 20u);  // 55 VPLs, most in view
    EXPECT_EQ(unlike, 0u);
}

}  // namespace
}  // namespace mvpl
