// engine/scene/scene_range.h at its edges: a value just inside a limit loads, just beyond it is
// refused with one InputError that names the place (JSON path, vertex, material) and the value.
// The bad-input corpus (test_bad_input.cpp) holds the far-out cases, one file each.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "engine/core/error.h"
#include "engine/scene/scene_loader.h"
#include "engine/scene/scene_range.h"

namespace mvpl::scene {
namespace {

namespace fs = std::filesystem;

class SceneRange : public ::testing::Test {
protected:
    void SetUp() override {
        m_dir = fs::temp_directory_path() / ("mvpl-scene-range-" + std::to_string(::getpid()));
        fs::create_directories(m_dir);
    }
    void TearDown() override { fs::remove_all(m_dir); }

    std::string write(const std::string& name, const std::string& text) const {
        const fs::path path = m_dir / name;
        std::ofstream(path, std::ios::binary) << text;
        return path.string();
    }

    // One triangle (0,0,0), (1,0,0), (0,1,0) on node 0 with `node` (JSON members) added to that
    // node, `material` as material 0 and `root` (JSON members) added to the document.
    std::string triangle(const std::string& node, const std::string& material = "{}",
                         const std::string& root = "") const {
        return write("scene.gltf", R"({"asset": {"version": "2.0"},
 "buffers": [{"byteLength": 42, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIA"}],
 "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                 {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
 "accessors": [{"componentType": 5126, "count": 3, "type": "VEC3", "bufferView": 0},
               {"componentType": 5123, "count": 3, "type": "SCALAR", "bufferView": 1}],
 "materials": [)" + material + R"(],
 "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
 "nodes": [{"mesh": 0)" + (node.empty() ? "" : ", " + node) +
                                       R"(}],
 "scenes": [{"nodes": [0]}], "scene": 0)" +
                                       (root.empty() ? "" : ", " + root) + "}\n");
    }

    fs::path m_dir;
};

// The InputError's message, or a test failure when the load succeeds or throws something else.
std::string refusal(const std::string& path) {
    try {
        load_scene(path);
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        return message;
    } catch (const std::exception& e) {
        ADD_FAILURE() << "not an InputError: " << e.what();
        return {};
    }
    ADD_FAILURE() << path << " loaded";
    return {};
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

TEST_F(SceneRange, PositionsUpToTheLimitLoadAndBeyondAreRefused) {
    // Translation and scale 5e8 put vertex 1 at exactly x = kMaxCoordinate.
    const Scene scene =
        load_scene(triangle(R"("translation": [5e8, 0, 0], "scale": [5e8, 5e8, 5e8])"));
    EXPECT_EQ(scene.bounds().hi.x, float(kMaxCoordinate));
    // Each node value within range, the vertex beyond it.
    const std::string message =
        refusal(triangle(R"("translation": [5e8, 0, 0], "scale": [5.0001e8, 1, 1])"));
    EXPECT_TRUE(contains(message,
                         "nodes[0] places accessors[0][1] (POSITION of mesh 0 primitive "
                         "0) at x = 1.00001e+09, beyond the supported magnitude 1e+09"))
        << message;
}

// The smallest scene (kMinSceneSize): the unit triangle scaled to 10⁻⁷ m across and a little
// more loads; scaled below, it is refused in one line that names the size; a scene of one point
// has no size at all.
TEST_F(SceneRange, ScenesBelowTheSmallestSizeAreRefused) {
    // The triangle's diagonal is √2 units: scale 10⁻⁷ makes it 1.41·10⁻⁷ m.
    EXPECT_NO_THROW(load_scene(triangle(R"("scale": [1e-7, 1e-7, 1e-7])")));
    EXPECT_TRUE(contains(refusal(triangle(R"("scale": [5e-8, 5e-8, 5e-8])")),
                         "smallest size rendered right (1e-07 m)"));
    EXPECT_TRUE(contains(refusal(triangle(R"("scale": [0, 0, 0])")), "is 0 m across"));
}

TEST_F(SceneRange, NodeValuesNameTheirJsonPath) {
    EXPECT_TRUE(contains(refusal(triangle(R"("translation": [0, 0, -2e11])")),
                         "nodes[0].translation[2] is -2e+11, beyond the supported magnitude"));
    EXPECT_TRUE(contains(refusal(triangle(R"("rotation": [0, 0, 1e300, 1])")),
                         "nodes[0].rotation[2] is 1e+300"));
    EXPECT_TRUE(
        contains(refusal(triangle(R"("scale": [1, 5e300, 1])")), "nodes[0].scale[1] is 5e+300"));
}

TEST_F(SceneRange, FactorsUpToTheLimitLoadAndBeyondAreRefused) {
    const Scene scene = load_scene(triangle("", R"({"emissiveFactor": [1e15, 0, 0]})"));
    EXPECT_EQ(scene.materials[0].emissive.r, float(kMaxFactor));
    EXPECT_TRUE(contains(refusal(triangle("", R"({"emissiveFactor": [0, 0, 2e15]})")),
                         "materials[0].emissiveFactor[2] is 2e+15, beyond the supported 1e+15"));
    // Clamped to 1 when in range, refused when a float could not hold it.
    EXPECT_EQ(load_scene(triangle("", R"({"pbrMetallicRoughness": {"roughnessFactor": 7}})"))
                  .materials[0]
                  .roughness,
              1.0f);
    EXPECT_TRUE(
        contains(refusal(triangle("", R"({"pbrMetallicRoughness": {"metallicFactor": 1e40}})")),
                 "materials[0].pbrMetallicRoughness.metallicFactor is 1e+40"));
    EXPECT_TRUE(contains(refusal(triangle("", R"({"extensions": {"KHR_materials_specular":
                                               {"specularColorFactor": [1, 1, 1e16]}}})")),
                         "materials[0].extensions.KHR_materials_specular.specularColorFactor[2] "
                         "is 1e+16"));
    EXPECT_TRUE(contains(refusal(triangle("", R"({"extensions": {"KHR_materials_ior":
                                               {"ior": 1e300}}})")),
                         "materials[0].extensions.KHR_materials_ior.ior is 1e+300"));
}

// KHR_materials_volume (issue 15, transmission): its thickness factor decides thin-walled (0, the
// default) or solid; a negative one is refused with its path.
TEST_F(SceneRange, VolumeThicknessIsReadAndANegativeOneRefused) {
    const Scene thin = load_scene(triangle("", R"({"extensions": {"KHR_materials_transmission":
                                               {"transmissionFactor": 1}}})"));
    EXPECT_EQ(thin.materials[0].transmission, 1.0f);
    EXPECT_EQ(thin.materials[0].thickness, 0.0f);
    const Scene solid = load_scene(triangle("", R"({"extensions": {"KHR_materials_transmission":
                                               {"transmissionFactor": 1}, "KHR_materials_volume":
                                               {"thicknessFactor": 0.25}}})"));
    EXPECT_EQ(solid.materials[0].thickness, 0.25f);
    EXPECT_TRUE(contains(refusal(triangle("", R"({"extensions": {"KHR_materials_volume":
                                               {"thicknessFactor": -1}}})")),
                         "materials[0].extensions.KHR_materials_volume.thicknessFactor"));
}

TEST_F(SceneRange, TextureRotationIsReducedToOneTurn) {
    const std::string texture =
        R"("images": [{"uri": "data:image/png;base64,iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAIAAACQd1PeAAAADElEQVR4nGNgZGIGAAAOAAfXb+R4AAAAAElFTkSuQmCC"}],
 "textures": [{"source": 0}])";
    const std::string material = R"({"pbrMetallicRoughness": {"baseColorTexture": {"index": 0,
        "extensions": {"KHR_texture_transform": {"rotation": 1e10}}}}})";
    const Scene scene = load_scene(triangle("", material, texture));
    const float rotation = scene.materials[0].base_color_texture.rotation;
    EXPECT_LE(std::abs(rotation), std::numbers::pi_v<float>);
    EXPECT_NEAR(rotation, std::remainder(1e10, 2.0 * std::numbers::pi), 1e-5);
}

TEST_F(SceneRange, PowerUpToTheLimitLoadsAndBeyondIsRefused) {
    // The triangle scaled by s has 0.5 s² m²; radiating kMaxFactor it emits π/2 · s² · 1e15 W.
    auto emitting = [&](double fraction_of_limit) {
        const double s =
            std::sqrt(fraction_of_limit * kMaxPower / (0.5 * std::numbers::pi * kMaxFactor));
        const std::string scale = std::to_string(s);
        return triangle(R"("scale": [)" + scale + ", " + scale + ", 1]",
                        R"({"emissiveFactor": [1e15, 1e15, 1e15]})");
    };
    EXPECT_NO_THROW(load_scene(emitting(0.999)));
    const std::string message = refusal(emitting(1.01));
    EXPECT_EQ(message.find("materials[0] (radiance 1e+15 W/(sr m^2) over "), message.find(": ") + 2)
        << message;
    EXPECT_TRUE(contains(message, "emits 1.01e+22 W, more than the supported 1e+22 W")) << message;
}

TEST_F(SceneRange, PowerOfSeveralEmittersIsCheckedTogether) {
    // Scaled by 1e4 the scene's bounding sphere has r ≈ 7071 m, so each directional light of
    // 4e13 W/m² lights π r² E ≈ 6.3e21 W: either alone would do, not both.
    const std::string lights = R"("extensions": {"KHR_lights_punctual": {"lights":
        [{"type": "directional", "intensity": 4e13}, {"type": "directional", "intensity": 4e13}]}})";
    const std::string nodes =
        R"("scale": [1e4, 1e4, 1e4], "children": [1, 2]},
           {"extensions": {"KHR_lights_punctual": {"light": 0}}},
           {"extensions": {"KHR_lights_punctual": {"light": 1}})";
    const std::string message = refusal(triangle(nodes, "{}", lights));
    EXPECT_TRUE(contains(message,
                         "the emitters emit 1.26e+22 W together (the most "
                         "extensions.KHR_lights_punctual.lights[0] (on nodes[1])"))
        << message;
    const std::string one_node =
        R"("scale": [1e4, 1e4, 1e4], "children": [1]},
           {"extensions": {"KHR_lights_punctual": {"light": 0}})";
    EXPECT_NO_THROW(load_scene(triangle(one_node, "{}", lights)));
}

TEST_F(SceneRange, CameraParameters) {
    auto with_camera = [&](const std::string& perspective) {
        return triangle(
            R"("children": [1]}, {"camera": 0, "translation": [0, 0, 5])", "{}",
            R"("cameras": [{"type": "perspective", "perspective": )" + perspective + "}]");
    };
    EXPECT_NO_THROW(load_scene(with_camera(R"({"yfov": 0.001, "znear": 0.1})")));
    EXPECT_NO_THROW(load_scene(with_camera(R"({"yfov": 2.5, "znear": 1e-20, "zfar": 100})")));
    EXPECT_TRUE(contains(refusal(with_camera(R"({"yfov": 0.0009, "znear": 0.1})")),
                         "cameras[0].perspective.yfov is 0.0009, outside the supported range "
                         "0.001 to 3.141591653589793"));
    EXPECT_TRUE(contains(refusal(with_camera(R"({"yfov": 3.1415925, "znear": 0.1})")),
                         "cameras[0].perspective.yfov is 3.1415925, outside"));
    EXPECT_TRUE(contains(refusal(with_camera(R"({"yfov": 0.5, "znear": 2e11})")),
                         "cameras[0].perspective.znear is 2e+11"));
    EXPECT_TRUE(contains(refusal(with_camera(R"({"yfov": 0.5, "znear": 1, "zfar": 0.5})")),
                         "cameras[0].perspective.zfar is 0.5, not beyond znear 1"));
}

TEST_F(SceneRange, ObjValuesAreCheckedToo) {
    write("m.mtl", "newmtl bright\nKd 0.5 0.5 0.5\nKe 1 1e20 1\n");
    const std::string factor =
        write("factor.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl bright\nf 1 2 3\n");
    EXPECT_TRUE(
        contains(refusal(factor), "material 'bright' has Ke 1e+20, beyond the supported 1e+15"));
    // π · 2e17 m² · 1e6 ≈ 6.4e23 W.
    write("p.mtl", "newmtl lamp\nKd 0.5 0.5 0.5\nKe 1e6 1e6 1e6\n");
    const std::string power = write(
        "power.obj", "mtllib p.mtl\nv 0 0 0\nv 6.4e8 0 0\nv 0 6.4e8 0\nusemtl lamp\nf 1 2 3\n");
    EXPECT_TRUE(contains(refusal(power),
                         "material 'lamp' (radiance 1e+06 W/(sr m^2) over "
                         "2.05e+17 m^2) emits 6.43e+23 W"));
}

TEST_F(SceneRange, ExternalImageRefusalSaysWhy) {
    fs::create_directories(m_dir / "folder.png");
    const std::string texture = R"("images": [{"uri": "folder.png"}], "textures": [{"source": 0}])";
    const std::string material = R"({"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}})";
    EXPECT_TRUE(contains(refusal(triangle("", material, texture)),
                         "image 0 file 'folder.png' is a directory, not a file"));
}

}  // namespace
}  // namespace mvpl::scene
