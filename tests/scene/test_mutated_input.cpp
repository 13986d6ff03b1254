// Deterministic mutation testing of the glTF and Mitsuba XML loaders: good fixtures with numbers
// swapped for hostile values, bytes flipped, slices cut out. Every result must either load into a
// scene that keeps the mesh invariants or throw mvpl::InputError, never anything else, and (under
// ASan/UBSan) never crash. MVPL_MUTATIONS=n raises the count per fixture for a longer campaign.
#include <gtest/gtest.h>

#include <unistd.h>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "engine/core/error.h"
#include "engine/scene/scene_loader.h"

namespace mvpl::scene {
namespace {

namespace fs = std::filesystem;

const char* const kHostileNumbers[] = {
    "-1", "0", "1", "2", "3", "7", "255", "256", "65535", "65536", "2147483647", "2147483648",
    "4294967295", "4294967296", "18446744073709551615", "1e308", "-1e308", "0.5", "1e-300", "-0",
    "5121", "5123", "5125", "5126", "34962",
    // Type confusion: where a number belongs.
    "\"x\"", "[]", "{}", "null", "true", "[0,0,0]", "{\"index\":0}"};

std::string read_file(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
}

void write_file(const fs::path& path, const std::string& content) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << content;
}

// Spans of JSON number tokens outside strings.
std::vector<std::pair<size_t, size_t>> number_tokens(const std::string& text) {
    std::vector<std::pair<size_t, size_t>> tokens;
    bool in_string = false;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (in_string) {
            if (c == '\\')
                ++i;
            else if (c == '"')
                in_string = false;
        } else if (c == '"') {
            in_string = true;
        } else if (c == '-' || (c >= '0' && c <= '9')) {
            size_t end = i + 1;
            while (end < text.size() &&
                   std::string_view("0123456789.eE+-").find(text[end]) != std::string_view::npos) {
                ++end;
            }
            tokens.emplace_back(i, end);
            i = end - 1;
        }
    }
    return tokens;
}

std::string mutate(const std::string& original, bool json, std::mt19937& rng) {
    std::string text = original;
    auto pick = [&](size_t n) { return std::uniform_int_distribution<size_t>(0, n - 1)(rng); };
    const int kind = int(pick(json ? 4 : 3));
    if (kind == 3) {  // a number becomes a hostile one; one to three times
        const auto tokens = number_tokens(text);
        if (tokens.empty()) return text;
        const size_t times = 1 + pick(3);
        for (size_t t = 0; t < times; ++t) {
            const auto refreshed = number_tokens(text);
            const auto [begin, end] = refreshed[pick(refreshed.size())];
            text.replace(begin, end - begin, kHostileNumbers[pick(std::size(kHostileNumbers))]);
        }
    } else if (kind == 0) {  // a few bytes change
        const size_t times = 1 + pick(4);
        for (size_t t = 0; t < times && !text.empty(); ++t)
            text[pick(text.size())] = char(pick(256));
    } else if (kind == 1) {  // truncation
        text.resize(pick(text.size() + 1));
    } else {  // a slice is cut out
        const size_t begin = pick(text.size());
        text.erase(begin, 1 + pick(std::min<size_t>(64, text.size() - begin)));
    }
    return text;
}

// A loaded scene must still satisfy what every consumer relies on.
std::string broken_invariant(const Scene& scene) {
    for (const Mesh& mesh : scene.meshes) {
        const size_t n = mesh.positions.size();
        if (mesh.normals.size() != n) return mesh.name + ": normals and positions differ in size";
        if (mesh.indices.empty() || mesh.indices.size() % 3 != 0)
            return mesh.name + ": bad index count";
        for (uint32_t index : mesh.indices) {
            if (index >= n) return mesh.name + ": index past the vertices";
        }
        for (size_t i = 0; i < n; ++i) {
            if (!is_finite(mesh.positions[i]) || !is_finite(mesh.normals[i])) {
                return mesh.name + ": non-finite vertex";
            }
        }
        if (mesh.material < 0 || size_t(mesh.material) >= scene.materials.size()) {
            return mesh.name + ": bad material";
        }
    }
    return scene.meshes.empty() ? "no meshes" : "";
}

class MutatedInput : public ::testing::TestWithParam<std::string> {};

TEST_P(MutatedInput, LoadsOrThrowsInputErrorOnly) {
    const fs::path source = GetParam();
    const fs::path dir =
        fs::temp_directory_path() /
        ("mvpl-mutations-" + std::to_string(::getpid()) + "-" + source.stem().string());
    fs::create_directories(dir);
    // The Cornell box keeps its geometry in cbox.bin next to it.
    const fs::path bin = source.parent_path() / "cbox.bin";
    if (source.filename() == "cbox.gltf")
        fs::copy_file(bin, dir / "cbox.bin", fs::copy_options::overwrite_existing);

    const std::string original = read_file(source);
    const bool json = source.extension() == ".gltf";
    const fs::path target = dir / ("mutant" + source.extension().string());
    const char* env = std::getenv("MVPL_MUTATIONS");
    const int count = env ? std::max(1, std::atoi(env)) : 60;
    std::mt19937 rng(12345u + unsigned(original.size()));
    int loaded = 0;
    for (int i = 0; i < count; ++i) {
        const std::string mutant = mutate(original, json, rng);
        write_file(target, mutant);
        try {
            const Scene scene = load_scene(target.string());
            ++loaded;
            const std::string problem = broken_invariant(scene);
            if (!problem.empty()) {
                write_file(dir / ("failure-" + std::to_string(i) + source.extension().string()),
                           mutant);
                ADD_FAILURE() << "mutation " << i << " loaded but " << problem;
            }
        } catch (const InputError& e) {
            const std::string message = e.what();
            // "PATH: what", or "PATH:LINE: what" for Mitsuba XML.
            const std::string path = target.string();
            size_t after = path.size();
            if (message.rfind(path + ":", 0) == 0) {
                after = path.size() + 1;
                while (after < message.size() &&
                       std::isdigit(static_cast<unsigned char>(message[after])))
                    ++after;
                if (after > path.size() + 1)
                    after = message[after] == ':' ? after : path.size();
                else
                    after = path.size();
            }
            if (message.rfind(path, 0) != 0 || message.compare(after, 2, ": ") != 0 ||
                message.find_first_of("\r\n") != std::string::npos) {
                ADD_FAILURE() << "mutation " << i << ": malformed message: " << message;
            }
        } catch (const std::exception& e) {
            write_file(dir / ("failure-" + std::to_string(i) + source.extension().string()),
                       mutant);
            ADD_FAILURE() << "mutation " << i << " threw a non-InputError: " << e.what();
        }
    }
    if (!HasFailure()) fs::remove_all(dir);
    RecordProperty("loaded", loaded);
}

INSTANTIATE_TEST_SUITE_P(
    Fixtures, MutatedInput,
    ::testing::Values(std::string(MVPL_TEST_DATA_DIR) + "/gltf/transforms.gltf",
                      std::string(MVPL_TEST_DATA_DIR) + "/gltf/flat_normals.gltf",
                      std::string(MVPL_TEST_DATA_DIR) + "/gltf/strip_fan.gltf",
                      std::string(MVPL_TEST_DATA_DIR) + "/gltf/materials.gltf",
                      std::string(MVPL_TEST_DATA_DIR) + "/gltf/lights_camera.gltf",
                      std::string(MVPL_TEST_DATA_DIR) + "/gltf/defaults.gltf",
                      std::string(MVPL_TEST_DATA_DIR) + "/gltf/box.glb",
                      std::string(MVPL_ASSETS_DIR) + "/cornell-box/cbox.gltf",
                      std::string(MVPL_TEST_DATA_DIR) + "/mitsuba/cbox.xml"),
    [](const ::testing::TestParamInfo<std::string>& info) {
        std::string name = fs::path(info.param).filename().string();
        for (char& c : name) {
            if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
        }
        return name;
    });

}  // namespace
}  // namespace mvpl::scene
