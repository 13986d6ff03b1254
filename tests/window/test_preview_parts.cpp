// The preview's window-free parts: the script format and the camera controller.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "engine/core/error.h"
#include "tools/preview/camera_controller.h"
#include "tools/preview/present_pass.h"
#include "tools/preview/preview_stats.h"
#include "tools/preview/screenshot_name.h"
#include "tools/preview/script.h"
#include "tools/preview/settings.h"
#include "tools/preview/settings_panel.h"
#include "tools/preview/window.h"
#include "tools/session/heat_colour.h"
#include "tools/session/vpl_dots.h"

// The preview's headers, like engine/gpu's, keep Vulkan (and GLFW) to their .cpp files.
#ifdef VULKAN_CORE_H_
#error "a preview or swapchain header includes <vulkan/vulkan.h>"
#endif
#ifdef _glfw3_h_
#error "a preview header includes GLFW"
#endif

namespace mvpl::preview {
namespace {

namespace fs = std::filesystem;

fs::path write_file(const std::string& name, const std::string& text) {
    const fs::path path = fs::temp_directory_path() / (name + std::to_string(::getpid()));
    std::ofstream(path) << text;
    return path;
}

TEST(PreviewScript, ParsesEventsInFrameOrder) {
    const fs::path path = write_file("script_ok",
                                     "# comment\n"
                                     "5 key escape\n"
                                     "\n"
                                     "2 resize 300 200  # trailing comment\n"
                                     "2 orbit -10 2.5\n"
                                     "3 fly 0.1 0 -0.2\n");
    const std::vector<ScriptEvent> events = load_script(path.string());
    ASSERT_EQ(events.size(), 4u);
    EXPECT_EQ(events[0].frame, 2u);
    EXPECT_EQ(events[0].action, "resize");  // file order within a frame
    EXPECT_EQ(events[0].values, (std::vector<float>{300.0f, 200.0f}));
    EXPECT_EQ(events[1].action, "orbit");
    EXPECT_EQ(events[1].values, (std::vector<float>{-10.0f, 2.5f}));
    EXPECT_EQ(events[2].values.size(), 3u);
    EXPECT_EQ(events[3].action, "key");
    EXPECT_EQ(events[3].key, "escape");
    fs::remove(path);
}

TEST(PreviewScript, ParsesSettingsCamerasAndDrops) {
    const fs::path path = write_file("script_settings",
                                     "1 set exposure -1.5\n"
                                     "1 set sampler metropolis\n"
                                     "1 set env_color 1 0.5 0.25\n"
                                     "2 camera 3\n"
                                     "2 fov 45\n"
                                     "3 drop /some folder/scene.glb  \n");
    const std::vector<ScriptEvent> events = load_script(path.string());
    ASSERT_EQ(events.size(), 6u);
    EXPECT_EQ(events[0].action, "set");
    EXPECT_EQ(events[0].key, "exposure");
    EXPECT_EQ(events[0].values, (std::vector<float>{-1.5f}));
    EXPECT_EQ(events[1].word, "metropolis");
    EXPECT_EQ(events[2].values, (std::vector<float>{1.0f, 0.5f, 0.25f}));
    EXPECT_EQ(events[3].values, (std::vector<float>{3.0f}));
    EXPECT_EQ(events[4].action, "fov");
    EXPECT_EQ(events[5].word, "/some folder/scene.glb");  // the rest of the line, trimmed
    fs::remove(path);
}

// Every setting the script names is one the table holds, once (the panel lists the table).
TEST(PreviewSettingsTable, NamesAreUniqueAndRangesChecked) {
    std::set<std::string> names;
    for (const SettingSpec& s : setting_specs()) {
        EXPECT_TRUE(names.insert(s.name).second) << s.name;
        EXPECT_EQ(find_setting(s.name), &s);
        if (s.values > 0) {
            EXPECT_EQ(check_setting_value(s, s.min), "") << s.name;
            EXPECT_NE(check_setting_value(s, s.max + 1.0f), "") << s.name;
        }
    }
    EXPECT_EQ(find_setting("nonesuch"), nullptr);
}

std::string joined(const std::vector<std::string>& lines) {
    std::string text;
    for (const std::string& line : lines)
        text += line + "\n";
    return text;
}

// The HUD says what the estimate has on, and VPL/s is VPLs over the last second's span: 500 at
// 0.5 s and 500 at 1 s after the first frame are 1000 VPL/s.
TEST(PreviewHud, SaysWhatIsOnAndTheRate) {
    PreviewStats stats;
    stats.frame_presented(0.01, 0.0, false);
    stats.add_vpls(500);
    stats.frame_presented(0.01, 0.5, false);
    stats.add_vpls(500);
    stats.frame_presented(0.01, 1.0, false);
    EXPECT_DOUBLE_EQ(stats.vpls_per_second(), 1000.0);
    HudState h;
    h.sampler = "mc";
    h.vpls = 1000;
    h.seconds = 2.5;
    h.parts.clamp = 0.1f;
    h.parts.compensation = false;
    h.parts.caustics = true;
    h.parts.vsl_radius = 0.03f;
    std::string text = joined(stats.hud_lines(h));
    for (const char* says : {"VPLs 1000", "1000 VPL/s", "2.5 s since restart",
                             "clamp 0.100 x diagonal, NOT compensated", "caustics on",
                             "specular chains off", "VSL radius 0.030"})
        EXPECT_NE(text.find(says), std::string::npos) << says << " not in\n" << text;
    h.parts.clamp = 0.0f;
    h.parts.caustics = false;
    h.parts.chains = true;
    h.parts.vsl_radius = 0.0f;
    text = joined(stats.hud_lines(h));
    for (const char* says : {"clamp off", "caustics off", "specular chains on", "VSL off"})
        EXPECT_NE(text.find(says), std::string::npos) << says << " not in\n" << text;
    EXPECT_EQ(text.find("row-column"), std::string::npos) << text;
    h.parts.pool = 8192;
    h.parts.clusters = 512;
    text = joined(stats.hud_lines(h));
    EXPECT_NE(text.find("row-column: pools of 8192 VPLs shaded as 512"), std::string::npos) << text;
    h.parts.clamp = 0.1f;
    h.parts.compensation = true;
    h.parts.moving = true;  // the CPU passes wait for the camera to rest
    text = joined(stats.hud_lines(h));
    EXPECT_NE(text.find("compensated (at rest)"), std::string::npos) << text;
}

// Screenshot names: the first number whose .png and .exr are both free, then the next.
TEST(ScreenshotName, SkipsNumbersInUse) {
    const fs::path folder = fs::temp_directory_path() / ("shots" + std::to_string(::getpid()));
    fs::remove_all(folder);
    fs::create_directories(folder);
    std::ofstream(folder / "cbox-0001.png") << "x";
    std::ofstream(folder / "cbox-0002.exr") << "x";
    uint32_t number = 1;
    EXPECT_EQ(next_screenshot(folder, "cbox", &number), folder / "cbox-0003");
    EXPECT_EQ(number, 4u);
    EXPECT_EQ(next_screenshot(folder, "cbox", &number), folder / "cbox-0004");
    EXPECT_EQ(next_screenshot(folder, "other", &number), folder / "other-0005");
    fs::remove_all(folder);
}

TEST(PreviewScript, RejectsMalformedLinesWithTheirNumber) {
    const struct {
        const char* text;
        const char* message;
    } cases[] = {
        {"x orbit 1 2\n", "line 1: expected a frame number"},
        {"1 orbit 1\n", "line 1: orbit needs 2 numbers"},
        {"\n1 zoom 0\n", "line 2: zoom needs a positive factor"},
        {"1 key q\n", "line 1: key needs one of r, plus, minus, m, c, p, v, tab, escape"},
        {"1 view albedos\n", "line 1: view needs image, albedo, normal, depth, vpls or error"},
        {"1 resize 0 10\n", "line 1: resize needs a size"},
        {"1 pan 1 2 3\n", "line 1: unexpected '3'"},
        {"-1 zoom 2\n", "line 1: expected a frame number"},
        {"1 set\n", "line 1: set needs a setting's name"},
        {"1 set gamma 2\n", "line 1: unknown setting 'gamma'"},
        {"1 set max_depth 0\n", "line 1: max_depth needs a whole number in [-1, 1024]"},
        {"1 set clamp 1.5\n", "line 1: clamp needs a number in [0, 1]"},
        {"1 set compensate 0.5\n", "line 1: compensate needs a whole number"},
        {"1 set env_color 1 1\n", "line 1: env_color needs 3 numbers"},
        {"1 set sampler bdpt\n", "line 1: sampler needs mc or metropolis"},
        {"1 camera -1\n", "line 1: camera needs a camera's index"},
        {"1 fov 180\n", "line 1: fov needs degrees in (0, 180)"},
        {"1 drop\n", "line 1: drop needs a file"},
    };
    for (const auto& c : cases) {
        const fs::path path = write_file("script_bad", c.text);
        try {
            load_script(path.string());
            ADD_FAILURE() << "accepted: " << c.text;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(c.message), std::string::npos) << e.what();
            EXPECT_EQ(std::string(e.what()).rfind(path.string(), 0), 0u) << e.what();
        }
        fs::remove(path);
    }
    EXPECT_THROW(load_script("/nonexistent/script.txt"), InputError);
}

scene::Bounds unit_box() {
    scene::Bounds b;
    b.lo = Vec3(-1.0f);
    b.hi = Vec3(1.0f);
    return b;
}

scene::Camera looking_at_origin() {
    scene::Camera c;
    c.camera_to_world = Mat4(1.0f);
    c.camera_to_world[3] = Vec4(0.0f, 0.0f, 5.0f, 1.0f);  // at +5 Z, looking down −Z
    return c;
}

// Tolerance: the controller rebuilds the frame with sin/cos/lookAt in float, errors ~1e-6
// relative per step on values of magnitude ≤ 5: 1e-4 leaves two orders of margin.
constexpr float kTolerance = 1e-4f;

// The dots' colour says the power against the largest, a decade a step of the ramp; an emitter
// VPL is ringed white; a VPL off the film or directional draws nothing.
TEST(VplDots, ColourAndRingSayPowerAndKind) {
    std::vector<light::Vpl> vpls(5);
    const float powers[] = {1.0f, 1e-3f, 1e-1f, 1.0f, 1.0f};
    for (size_t i = 0; i < vpls.size(); ++i) {
        vpls[i].type = light::VplType::Surface;
        vpls[i].path_length = 1;
        vpls[i].power = Rgb(powers[i]);
        vpls[i].position = Vec3(20.0f + 40.0f * float(i), 20.0f, 0.0f);  // film = (x, y)
    }
    vpls[2].path_length = 0;
    vpls[3].position.x = -100.0f;
    vpls[4].type = light::VplType::Directional;
    Image image(200, 40);
    const size_t drawn = session::draw_vpls(
        image,
        [&](const Vec3& p, Vec2& film) {
            film = Vec2(p.x, p.y);
            return p.x >= 0.0f;
        },
        vpls);
    EXPECT_EQ(drawn, 3u);
    const auto at = [&](float x) { return image.at(int(x), 20); };
    EXPECT_TRUE(at(20.0f) == Rgb(1.0f, 0.0f, 0.0f));  // the largest: red
    EXPECT_TRUE(at(60.0f) == Rgb(0.0f, 0.0f, 1.0f));  // 10⁻³ of it: blue
    EXPECT_TRUE(at(100.0f) == session::dot_colour(0.1f));
    EXPECT_NEAR(session::dot_colour(0.1f).r, 1.0f, 1e-5f);  // 10⁻¹: yellow
    EXPECT_NEAR(session::dot_colour(0.1f).g, 1.0f, 1e-5f);
    // The emitter's ring: a white pixel just outside its disc, none beside the others.
    size_t white = 0;
    for (int x = 0; x < image.width(); ++x)
        for (int y = 0; y < image.height(); ++y)
            if (image.at(x, y) == session::kEmitterRing) {
                EXPECT_NEAR(float(x), 100.0f, 4.0f);
                ++white;
            }
    EXPECT_GT(white, 4u);
    // Every power's colour is on the ramp that tests find dots by; a radiance is not.
    for (const float rel : {1.0f, 0.5f, 0.1f, 0.03f, 0.01f, 0.003f, 1e-3f, 1e-5f, 0.0f})
        EXPECT_TRUE(session::on_heat_ramp(session::dot_colour(rel))) << rel;
    EXPECT_FALSE(session::on_heat_ramp(Rgb(0.3f, 0.2f, 0.1f)));
    EXPECT_FALSE(session::on_heat_ramp(Rgb(0.0f, 0.0f, 0.0f)));
}

TEST(CameraController, UnmovedCameraIsTheScenesExactly) {
    const scene::Camera c = looking_at_origin();
    CameraController controller(c, unit_box());
    EXPECT_EQ(controller.camera().camera_to_world, c.camera_to_world);
    controller.orbit(30.0f, 10.0f);
    EXPECT_NE(controller.camera().camera_to_world, c.camera_to_world);
    controller.reset();
    EXPECT_EQ(controller.camera().camera_to_world, c.camera_to_world);
}

TEST(CameraController, OrbitKeepsTheDistanceToTheTarget) {
    CameraController controller(looking_at_origin(), unit_box());
    controller.orbit(90.0f, 0.0f);
    // A quarter turn about +Y around the origin (the target: the box's centre on the view axis).
    const Vec3 p = controller.camera().position();
    EXPECT_NEAR(glm::length(p), 5.0f, kTolerance);
    EXPECT_NEAR(p.y, 0.0f, kTolerance);
    EXPECT_NEAR(std::abs(p.x), 5.0f, kTolerance);
    // Still looking at the origin.
    const Vec3 forward = -Vec3(controller.camera().camera_to_world[2]);
    EXPECT_NEAR(glm::dot(forward, -glm::normalize(p)), 1.0f, kTolerance);
    controller.orbit(270.0f, 0.0f);  // full circle: back where it started
    EXPECT_NEAR(glm::length(controller.camera().position() - Vec3(0.0f, 0.0f, 5.0f)), 0.0f,
                kTolerance);
}

TEST(CameraController, ZoomPanAndFlyMoveAsDocumented) {
    CameraController controller(looking_at_origin(), unit_box());
    controller.zoom(0.5f);
    EXPECT_NEAR(controller.camera().position().z, 2.5f, kTolerance);
    controller.pan(0.5f, 0.0f);  // half the view height at the target, to the right (+X)
    const float height = 2.0f * 2.5f * std::tan(0.5f * controller.camera().yfov);
    EXPECT_NEAR(controller.camera().position().x, 0.5f * height, kTolerance);
    const Vec3 before = controller.camera().position();
    controller.fly(0.25f, 0.0f, 0.0f);  // a quarter of the diagonal (2·√3) forward (−Z)
    const Vec3 moved = controller.camera().position() - before;
    EXPECT_NEAR(moved.z, -0.25f * 2.0f * std::sqrt(3.0f), kTolerance);
    EXPECT_NEAR(moved.x, 0.0f, kTolerance);
}

}  // namespace
}  // namespace mvpl::preview
