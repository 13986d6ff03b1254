// Which camera a command renders from (issue 12, "Camera"): --camera N among the file's
// perspective cameras, --look-at and --fov overriding it, with one-line errors for what does not
// exist; and the loader's warnings (an extension it ignores) reach stderr.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "engine/core/image.h"
#include "tests/cli/run_command.h"

namespace mvpl {
namespace {

using test::expect_one_line_error;
namespace fs = std::filesystem;

std::string temp(const std::string& name) {
    return (fs::temp_directory_path() / ("mvpl_camera_" + std::to_string(::getpid()) + "_" + name))
        .string();
}

// The lit room of wide_angle.gltf with a 1-radian camera and a second node carrying it, at
// another place: two perspective cameras that see different pictures.
std::string write_two_camera_room() {
    std::ifstream in(MVPL_TEST_DATA_DIR "/gltf/wide_angle.gltf");
    nlohmann::json doc = nlohmann::json::parse(in);
    doc["cameras"][0]["perspective"]["yfov"] = 1.0;
    doc["nodes"].push_back({{"camera", 0}, {"translation", {-0.3, 0.1, 0.4}}});
    doc["scenes"][0]["nodes"].push_back(doc["nodes"].size() - 1);
    const std::string path = temp("two_cameras.gltf");
    std::ofstream(path) << doc.dump();
    return path;
}
const std::string kTwoCameras = write_two_camera_room();

Image reference(const std::string& scene, const std::string& flags, const std::string& name) {
    const std::string out = temp(name + ".exr");
    const test::CommandResult r = test::run_mvpl(
        "reference " + scene + " --spp 4 --res 24x16 --quiet -o " + out + " " + flags);
    EXPECT_EQ(r.exit_code, 0) << flags << ": " << r.err;
    Image image = read_exr(out);
    fs::remove(out);
    return image;
}

double difference(const Image& a, const Image& b) {
    double d = 0.0;
    for (size_t i = 0; i < a.pixels().size(); ++i) {
        for (int c = 0; c < 3; ++c)
            d += std::abs(a.pixels()[i][c] - b.pixels()[i][c]);
    }
    return d;
}

TEST(CameraOptions, CameraNPicksTheFilesNthCameraAndRefusesOneItLacks) {
    const Image first = reference(kTwoCameras, "", "default");
    EXPECT_GT(first.mean().r, 0.0f);
    EXPECT_EQ(difference(reference(kTwoCameras, "--camera 0", "zero"), first), 0.0);
    const Image second = reference(kTwoCameras, "--camera 1", "one");
    EXPECT_GT(difference(second, first), 0.0) << "the second camera sees another view";
    expect_one_line_error(
        test::run_mvpl("reference " + kTwoCameras + " --camera 2 -o " + temp("x.exr")),
        "--camera 2: " + kTwoCameras + " has 2 perspective cameras (0..1)");
    expect_one_line_error(
        test::run_mvpl_gpu("render " + kTwoCameras + " --camera 7 -o " + temp("x.exr")),
        "has 2 perspective cameras");
}

// --look-at at the second camera's place and aim reproduces it; --fov changes the view.
TEST(CameraOptions, LookAtAndFovOverrideTheCamera) {
    const Image first = reference(kTwoCameras, "", "default2");
    const Image moved = reference(kTwoCameras, "--look-at 0.2,0.1,0.3,0,0,-1", "moved");
    EXPECT_GT(difference(moved, first), 0.0);
    const Image up_z = reference(kTwoCameras, "--look-at 0.2,0.1,0.3,0,0,-1,1,0,0", "rolled");
    EXPECT_GT(difference(up_z, moved), 0.0) << "the up vector rolls the image";
    const Image wide = reference(kTwoCameras, "--fov 90", "wide");
    EXPECT_GT(difference(wide, first), 0.0);
    for (const char* bad : {"--look-at 1,2,3,4,5", "--look-at 1,2,3,1,2,3", "--look-at 1,2,x,0,0,0",
                            "--fov 180", "--fov -1", "--camera -2"}) {
        const test::CommandResult r = test::run_mvpl("reference " + kTwoCameras + " " +
                                                     std::string(bad) + " -o " + temp("x.exr"));
        expect_one_line_error(r, "reference: --");
    }
}

// An extension the file uses but mvpl ignores is named in one warning line; the render goes on.
TEST(CameraOptions, AnIgnoredExtensionIsNamedOnce) {
    std::ifstream in(MVPL_TEST_DATA_DIR "/gltf/defaults.gltf");
    std::stringstream text;
    text << in.rdbuf();
    std::string json = text.str();
    json.insert(json.find('{') + 1,
                "\"extensionsUsed\": [\"KHR_materials_clearcoat\", \"KHR_texture_transform\"],");
    const std::string path = temp("clearcoat.gltf");
    std::ofstream(path) << json;
    const test::CommandResult r =
        test::run_mvpl("reference " + path + " --spp 1 --res 8x8 --quiet -o " + temp("c.exr"));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("mvpl: warning: " + path +
                         ": extension KHR_materials_clearcoat is not supported; it is ignored\n"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(r.err.find("KHR_texture_transform"), std::string::npos) << "supported: no warning";
    fs::remove(path);
    fs::remove(temp("c.exr"));
}

}  // namespace
}  // namespace mvpl
