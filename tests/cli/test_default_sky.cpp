// When the default sky is added (light::SceneLighting, engine/light/default_sky.h) and what a
// dark or black image is told (issue 32, item 5): a model lit only by its emissive texture (the
// Khronos WaterBottle and DamagedHelmet of ../shared/gltf-samples; skips without them) gets the
// sky and one line saying so; the project's scenes lit by their area lights get none; a camera
// whose znear clips everything away is told that, not that no light arrives.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "engine/core/image.h"
#include "tests/cli/run_command.h"

namespace mvpl {
namespace {

namespace fs = std::filesystem;
using test::run_mvpl;
using test::run_mvpl_gpu;
using test::shell_quote;

const fs::path kSamples = fs::path(MVPL_SOURCE_DIR) / ".." / "shared" / "gltf-samples";

std::string temp_file(const std::string& name) {
    return test::temp_file("mvpl_sky", name);
}

// The thresholds. Under the unit sky the background alone is radiance 1 wherever the model is
// not (more than half of the frame at the files' framings), so the lit image's mean luminance
// is above 0.5 whatever the model reflects (measured 0.85 and 0.83 at 64²); lit by its emissive
// texture alone it is 2·10⁻⁵ (WaterBottle: 34 glowing pixels of 128²) and 2·10⁻³ (DamagedHelmet,
// 166 of 64², the mean before this rule), far below 0.05.
constexpr float kLitMean = 0.5f;
constexpr float kDarkMean = 0.05f;

// DamagedHelmet (its emission is 0.64 % of the unit sky's flux; before this rule it got no sky
// and rendered at mean 0.002 with no warning) and SpecGlossVsMetalRough (its WaterBottles' only
// light is their emissive texture, 0.36 %).
TEST(DefaultSky, ModelsLitOnlyByTheirEmissiveTexturesGetTheSky) {
    for (const char* name : {"DamagedHelmet", "SpecGlossVsMetalRough"}) {
        SCOPED_TRACE(name);
        const fs::path model = kSamples / name / "glTF" / (std::string(name) + ".gltf");
        if (!fs::exists(model)) GTEST_SKIP() << "../shared/gltf-samples is not there";
        const std::string lit = temp_file("lit.exr"), dark = temp_file("dark.exr");
        const std::string common =
            "render " + shell_quote(model.string()) + " --res 64x64 --vpls 256 --quiet ";
        const auto r = run_mvpl_gpu(common + "-o " + shell_quote(lit));
        ASSERT_EQ(r.exit_code, 0) << r.err;
        EXPECT_NE(r.err.find("emissive surfaces"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("uniform white sky"), std::string::npos) << r.err;
        EXPECT_GT(luminance(read_exr(lit).mean()), kLitMean);
        // Without the sky the picture is dark, and one line says why.
        const auto d = run_mvpl_gpu(common + "--no-default-light -o " + shell_quote(dark));
        ASSERT_EQ(d.exit_code, 0) << d.err;
        EXPECT_NE(d.err.find("the image is dark"), std::string::npos) << d.err;
        EXPECT_LT(luminance(read_exr(dark).mean()), kDarkMean);
        fs::remove(lit);
        fs::remove(dark);
    }
}

TEST(DefaultSky, ScenesLitByTheirAreaLightsGetNone) {
    for (const char* scene : {"cornell-box/cbox.gltf", "two-room/two-room.gltf"}) {
        const std::string path = std::string(MVPL_ASSETS_DIR) + "/" + scene;
        const auto r =
            run_mvpl("reference " + shell_quote(path) + " --res 4x4 --spp 1 --quiet -o " +
                     shell_quote(temp_file("area.exr")));
        ASSERT_EQ(r.exit_code, 0) << r.err;
        EXPECT_EQ(r.err.find("sky"), std::string::npos) << scene << ": " << r.err;
    }
    fs::remove(temp_file("area.exr"));
}

// The Cornell box with its camera's znear beyond the whole box: black, and the warning says why.
TEST(BlackImage, ACameraWhoseZnearClipsEverythingIsToldSo) {
    const fs::path dir = temp_file("znear");
    fs::create_directories(dir);
    const fs::path assets = fs::path(MVPL_ASSETS_DIR) / "cornell-box";
    fs::copy_file(assets / "cbox.bin", dir / "cbox.bin", fs::copy_options::overwrite_existing);
    std::stringstream text;
    text << std::ifstream(assets / "cbox.gltf").rdbuf();
    std::string gltf = text.str();
    const size_t at = gltf.find("\"znear\"");
    ASSERT_NE(at, std::string::npos);
    gltf.replace(at, gltf.find(',', at) - at, "\"znear\": 2700");
    std::ofstream(dir / "cbox.gltf") << gltf;
    const std::string scene = shell_quote((dir / "cbox.gltf").string());
    const std::string out = shell_quote((dir / "x.exr").string());
    for (const std::string& command : {"reference " + scene + " --res 16x16 --spp 1",
                                       "render " + scene + " --res 16x16 --vpls 16"}) {
        const auto r = run_mvpl_gpu(command + " --quiet -o " + out);
        ASSERT_EQ(r.exit_code, 0) << r.err;
        EXPECT_NE(r.err.find("nearer than its znear (2700)"), std::string::npos) << r.err;
        EXPECT_EQ(r.err.find("no light"), std::string::npos) << r.err;
        EXPECT_EQ(read_exr((dir / "x.exr").string()).mean(), Rgb(0.0f));
    }
    fs::remove_all(dir);
}

}  // namespace
}  // namespace mvpl
