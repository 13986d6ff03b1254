// The bad-input corpus: every file in tests/data/bad must be refused with exactly one
// mvpl::InputError, whose message starts with the file's path and fits on one line; nothing else
// may be thrown (and, run under ASan/UBSan, nothing may crash, leak or overflow).
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "engine/core/error.h"
#include "engine/scene/scene_loader.h"

namespace mvpl::scene {
namespace {

const std::string kBadDir = std::string(MVPL_TEST_DATA_DIR) + "/bad";

// What each file's message must mention, so that a file fails for the defect it is named after
// rather than for an accident on the way. Files not listed are only held to the general rules.
const std::map<std::string, std::string> kExpected = {
    {"empty.gltf", "file is empty"},
    {"empty.glb", "file is empty"},
    {"not-json.gltf", "invalid JSON"},
    {"truncated-json.gltf", "invalid JSON"},
    {"json-root-is-array.gltf", "not a JSON object"},
    {"missing-asset.gltf", "\"asset\""},
    {"gltf-version-1.gltf", "glTF version '1.0' is not supported"},
    {"deep-nesting.gltf", "nested deeper"},
    {"accessor-past-buffer-view.gltf",
     "accessor 0 (POSITION of mesh 0 primitive 0) reads past the end of buffer view 0"},
    {"accessor-past-buffer.gltf",
     "buffer view 0 (offset 0, length 100) extends past the end of buffer 0"},
    {"accessor-offset-overflow.gltf", "reads past the end of buffer view 0"},
    {"buffer-view-offset-overflow.gltf", "extends past the end of buffer 0"},
    {"absurd-accessor-count.gltf", "reads past the end of buffer view 0: 4000000000 elements"},
    {"absurd-count-without-buffer-view.gltf", "no buffer view and 300000000 elements"},
    {"negative-buffer-length.gltf", "buffer 0 byteLength -44 is not a non-negative integer"},
    {"absurd-buffer-length.gltf", "does not match the 42 bytes of its data URI"},
    {"empty-data-uri-buffer.gltf", "buffer 0 has an empty data URI"},
    {"stride-smaller-than-element.gltf", "byteStride of 4"},
    {"bad-accessor-index.gltf", "refers to accessor 9"},
    {"position-not-vec3.gltf", "must be VEC3, not VEC2"},
    {"position-unsigned-byte.gltf", "unsigned byte components"},
    {"no-position.gltf", "no POSITION"},
    {"invalid-mode.gltf", "invalid mode 9"},
    {"lines-only.gltf", "no triangle geometry"},
    {"points-only.gltf", "no triangle geometry"},
    {"index-count-not-multiple-of-3.gltf", "not a multiple of 3"},
    {"index-past-vertex-count.gltf", "index 7 at element 2, past the vertex count 3"},
    {"bad-material-index.gltf", "refers to material 5"},
    {"bad-node-mesh-index.gltf", "node 0 refers to mesh 2"},
    {"bad-default-scene.gltf", "default scene 4 does not exist"},
    {"scene-bad-node-index.gltf", "refers to node 7"},
    {"node-cycle.gltf", "node cycle through node 1"},
    {"node-self-child.gltf", "node cycle through node 0"},
    {"node-two-parents.gltf", "node 2 has two parents"},
    {"node-bad-child-index.gltf", "has child 3"},
    {"number-overflow-in-matrix.gltf", "invalid JSON: number overflow"},
    {"position-beyond-float-range.gltf",
     "nodes[0].translation[0] is 1e+39, beyond the supported magnitude 1e+09"},
    {"nan-transform.gltf", "non-finite world transform"},
    {"nan-literal-in-transform.gltf", "invalid JSON"},
    {"zero-quaternion.gltf", "zero rotation quaternion"},
    {"wrong-matrix-length.gltf", "matrix of 4 numbers"},
    {"inf-position.gltf", "non-finite value at element 1"},
    {"nan-position.gltf", "non-finite value at element 2"},
    {"missing-external-buffer.gltf", "buffer 0 file 'missing-buffer.bin' not found"},
    {"buffer-uri-is-device.gltf", "is not a regular file"},
    {"required-extension-unsupported.gltf",
     "required extension KHR_draco_mesh_compression is not supported"},
    {"bad-texture-index.gltf", "refers to texture 3"},
    {"texcoord-set-2.gltf", "TEXCOORD_2"},
    {"missing-external-image.gltf", "image 0 file 'missing-image.png' not found"},
    {"image-undecodable.gltf", "image 0 cannot be decoded: corrupt or truncated PNG"},
    {"image-corrupt-jpeg.gltf", "image 0 cannot be decoded: corrupt or truncated JPEG"},
    {"images-cut-short.gltf", "image 0 cannot be decoded"},
    {"image-webp-as-png.gltf",
     "image 0 cannot be decoded: WebP (EXT_texture_webp), which is not supported"},
    {"image-huge-dimensions.gltf", "16384x16384"},
    {"image-buffer-view-past-buffer.gltf", "extends past the end of buffer 0"},
    {"texture-without-source.gltf", "no image source"},
    {"bad-sampler-wrap.gltf", "invalid wrapS 1234"},
    {"negative-material-factor.gltf",
     "materials[0].pbrMetallicRoughness.roughnessFactor is -0.5, which is negative"},
    {"ior-below-one.gltf", "below 1"},
    {"unknown-alpha-mode.gltf", "materials[0].alphaMode is 'CUTOUT', not OPAQUE, MASK or BLEND"},
    {"bad-light-index.gltf", "refers to light 3"},
    {"spot-inner-above-outer.gltf", "invalid cone angles"},
    {"bad-camera-index.gltf", "refers to camera 2"},
    {"camera-zero-yfov.gltf", "cameras[0].perspective.yfov is 0, outside the supported range"},
    {"sparse-index-past-count.gltf", "sparse index 5"},
    {"normal-count-mismatch.gltf", "has 2 elements but POSITION has 3"},
    {"truncated.glb", "truncated GLB"},
    {"glb-short-header.glb", "truncated GLB"},
    {"glb-bad-version.glb", "GLB version 1"},
    {"glb-length-past-end.glb", "truncated GLB"},
    {"glb-bad-json-chunk-length.glb",
     "the GLB JSON chunk (2147483632 bytes at offset 20) runs past the end"},
    {"glb-bin-chunk-past-end.glb", "the GLB BIN chunk (52 bytes at offset 524) runs past the end"},
    {"glb-without-bin-chunk.glb", "the GLB has no BIN chunk"},
    {"unknown-extension.xyz", "unsupported scene format"},
    // Values finite as doubles but beyond engine/scene/scene_range.h (tests/data/gltf/
    // range_fixtures.py): each names its JSON path and its value.
    {"translation-beyond-range.gltf",
     "nodes[0].translation[1] is 1e+12, beyond the supported magnitude 1e+09"},
    {"matrix-beyond-range.gltf", "nodes[0].matrix[12] is 3e+38, beyond the supported magnitude"},
    {"vertex-beyond-range.gltf",
     "nodes[0] places accessors[0][1] (POSITION of mesh 0 primitive 0) at x = 2e+12, beyond the "
     "supported magnitude 1e+09"},
    {"scaled-vertex-beyond-range.gltf",
     "nodes[0] places accessors[0][1] (POSITION of mesh 0 primitive 0) at x = 1e+10"},
    {"random-bytes-positions.gltf", "beyond the supported magnitude 1e+09"},
    {"emissive-factor-beyond-range.gltf",
     "materials[0].emissiveFactor[0] is 1e+308, beyond the supported 1e+15"},
    {"emissive-strength-product-beyond-range.gltf",
     "materials[0] emissiveFactor x emissiveStrength is 1e+20, beyond the supported 1e+15"},
    {"base-color-factor-beyond-range.gltf",
     "materials[0].pbrMetallicRoughness.baseColorFactor[1] is 1e+300"},
    {"texture-transform-scale-beyond-range.gltf",
     "materials[0].pbrMetallicRoughness.baseColorTexture.extensions.KHR_texture_transform.scale[0]"
     " is 1e+308, beyond the supported magnitude 1e+15"},
    {"texture-transform-offset-beyond-range.gltf", "KHR_texture_transform.offset[1] is -3e+38"},
    {"light-intensity-beyond-range.gltf",
     "extensions.KHR_lights_punctual.lights[0].intensity is 1e+38, beyond the supported 1e+15"},
    {"light-color-beyond-range.gltf", "extensions.KHR_lights_punctual.lights[0].color[1] is 1e+20"},
    {"light-position-beyond-range.gltf",
     "nodes[1] places extensions.KHR_lights_punctual.lights[0] at z = 1e+12"},
    {"directional-light-power-beyond-range.gltf",
     "emits 1.57e+23 W, more than the supported 1e+22 W"},
    {"area-light-power-beyond-range.gltf",
     "materials[0] (radiance 1e+06 W/(sr m^2) over 2.05e+17 m^2) emits 6.43e+23 W"},
    {"camera-yfov-tiny.gltf", "cameras[0].perspective.yfov is 1e-30, outside the supported range"},
    {"camera-yfov-pi.gltf", "cameras[0].perspective.yfov is 3.14159265358979, outside"},
    {"camera-znear-tiny.gltf", "cameras[0].perspective.znear is 1e-30, outside the supported"},
    {"camera-position-beyond-range.gltf", "nodes[1] places cameras[0] at z = 1e+12"},
    {"obj-vertex-beyond-range.obj", "vertex 2 has x = 2e+12, beyond the supported magnitude 1e+09"},
    {"ply-vertex-beyond-range.ply", "vertex 2 has y = 5e+13, beyond the supported magnitude"},
    {"ply-vertex-beyond-range-binary.ply", "vertex 1 has z = -3e+20"},
    // The cause, not its consequences.
    {"draco-required-before-accessor-error.gltf",
     "required extension KHR_draco_mesh_compression is not supported"},
    {"no-file-extension", "unsupported scene format"},
    // Mitsuba XML (issue 16): FILE:LINE of the element at fault.
    {"mitsuba-unclosed-tag.xml",
     "mitsuba-unclosed-tag.xml:4: malformed XML: Start-end tags mismatch"},
    {"mitsuba-unknown-reference.xml", "mitsuba-unknown-reference.xml:3: unknown reference 'nope'"},
    {"mitsuba-missing-file.xml", "mitsuba-missing-file.xml:3: file 'not-there.obj' not found"},
    {"mitsuba-negative-radius.xml",
     "mitsuba-negative-radius.xml:2: sphere radius must be positive"},
    {"mitsuba-nan-matrix.xml", "mitsuba-nan-matrix.xml:4: value 'nan' is not a finite number"},
    {"mitsuba-unsupported-bsdf.xml",
     "mitsuba-unsupported-bsdf.xml:2: bsdf type 'hair' is not supported"},
    {"mitsuba-undefined-parameter.xml",
     "mitsuba-undefined-parameter.xml:3: undefined parameter '$r'"},
    {"mitsuba-include-cycle.xml", "mitsuba-include-cycle.xml:2: includes nest deeper than 16"},
    {"mitsuba-root-not-scene.xml", "the root element is <film>, not <scene>"},
    {"mitsuba-bad-serialized.xml", "not a Mitsuba serialized mesh"},
    {"mitsuba-proc-file.xml", "mitsuba-proc-file.xml:3: '/proc/self/status' is not a regular file"},
    {"mitsuba-lookat-origin-is-target.xml",
     "mitsuba-lookat-origin-is-target.xml:4: lookat: the origin is the target"},
    {"mitsuba-sensor-up-along-view.xml",
     "mitsuba-sensor-up-along-view.xml:2: the sensor's up is parallel to its view direction"},
    {"mitsuba-lookat-up-along-view.xml",
     "mitsuba-lookat-up-along-view.xml:4: lookat: up is zero or parallel to the view direction"},
    {"mitsuba-default-expansion.xml", "expands past 1 MiB"},
    {"camera-up-along-view.gltf", "with a degenerate transform"},
};

// "PATH: " or, for a file with lines (Mitsuba XML), "PATH:LINE: ".
bool names_the_file(const std::string& message, const std::string& path) {
    if (message.rfind(path + ": ", 0) == 0) return true;
    if (message.rfind(path + ":", 0) != 0) return false;
    size_t i = path.size() + 1;
    const size_t digits = i;
    while (i < message.size() && std::isdigit(static_cast<unsigned char>(message[i])))
        ++i;
    return i > digits && message.compare(i, 2, ": ") == 0;
}

std::vector<std::string> corpus() {
    std::vector<std::string> files;
    for (const auto& entry : std::filesystem::directory_iterator(kBadDir)) {
        if (entry.is_regular_file()) files.push_back(entry.path().filename().string());
    }
    std::sort(files.begin(), files.end());
    return files;
}

class BadInput : public ::testing::TestWithParam<std::string> {};

TEST_P(BadInput, ThrowsOneLineInputErrorNamingTheFile) {
    const std::string path = kBadDir + "/" + GetParam();
    try {
        const Scene scene = load_scene(path);
        ADD_FAILURE() << path << " loaded (" << scene.meshes.size()
                      << " meshes) instead of failing";
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_TRUE(names_the_file(message, path)) << message;
        EXPECT_EQ(message.find_first_of("\r\n"), std::string::npos) << message;
        EXPECT_GT(message.size(), path.size() + 2) << "no reason given";
        const auto expected = kExpected.find(GetParam());
        if (expected != kExpected.end()) {
            EXPECT_NE(message.find(expected->second), std::string::npos)
                << "expected '" << expected->second << "' in: " << message;
        }
    } catch (const std::exception& e) {
        ADD_FAILURE() << path << " threw something other than InputError: " << e.what();
    } catch (...) {
        ADD_FAILURE() << path << " threw a non-exception";
    }
}

INSTANTIATE_TEST_SUITE_P(Corpus, BadInput, ::testing::ValuesIn(corpus()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             std::string name = info.param;
                             for (char& c : name) {
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             }
                             return name;
                         });

TEST(BadInputCorpus, HoldsEveryDocumentedCase) {
    const std::vector<std::string> files = corpus();
    for (const auto& [name, reason] : kExpected) {
        EXPECT_TRUE(std::binary_search(files.begin(), files.end(), name)) << name << " is missing";
    }
}

}  // namespace
}  // namespace mvpl::scene
