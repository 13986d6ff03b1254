// The bad-input corpus: every file in tests/data/bad must be refused with exactly one
// mvpl::InputError, whose message starts with the file's path and fits on one line; nothing else
// may be thrown (and, run under ASan/UBSan, nothing may crash, leak or overflow).
#include <gtest/gtest.h>

#include <algorithm>
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
    {"position-beyond-float-range.gltf", "outside the range of float coordinates"},
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
    {"missing-external-image.gltf", "missing-image.png"},
    {"image-undecodable.gltf", "image 0 cannot be decoded"},
    {"image-huge-dimensions.gltf", "16384x16384"},
    {"image-buffer-view-past-buffer.gltf", "extends past the end of buffer 0"},
    {"texture-without-source.gltf", "no image source"},
    {"bad-sampler-wrap.gltf", "invalid wrapS 1234"},
    {"negative-material-factor.gltf", "roughnessFactor is negative"},
    {"ior-below-one.gltf", "below 1"},
    {"bad-light-index.gltf", "refers to light 3"},
    {"spot-inner-above-outer.gltf", "invalid cone angles"},
    {"bad-camera-index.gltf", "refers to camera 2"},
    {"camera-zero-yfov.gltf", "invalid yfov"},
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
    {"no-file-extension", "unsupported scene format"},
};

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
        EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
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
