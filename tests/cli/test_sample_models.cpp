// Every Khronos sample model in ../shared/gltf-samples (beside a checkout in this workplace; the
// test skips without them) loads and renders with exit 0 and a finite image, on the GPU and with
// the path tracer, lit as the user gets it: its own lights, or the default sky when it has none
// (issue 12); writing an image refuses NaNs and infinities (engine/core/finite_check.h). And the
// GPU image agrees with the path tracer's within a bound derived from the two methods' own noise.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "engine/core/image.h"
#include "tests/cli/run_command.h"

namespace mvpl {
namespace {

namespace fs = std::filesystem;
using test::run_mvpl;
using test::run_mvpl_gpu;
using test::shell_quote;

std::vector<fs::path> sample_models() {
    const fs::path root = fs::path(MVPL_SOURCE_DIR) / ".." / "shared" / "gltf-samples";
    std::vector<fs::path> out;
    std::error_code ec;
    for (const fs::directory_entry& d : fs::directory_iterator(root, ec)) {
        const fs::path gltf = d.path() / "glTF" / (d.path().filename().string() + ".gltf");
        if (fs::exists(gltf)) out.push_back(gltf);
    }
    std::sort(out.begin(), out.end());
    return out;
}

// relMSE of image a against image b (mvpl compare).
double rel_mse(const std::string& a, const std::string& b) {
    const auto r = run_mvpl("compare " + shell_quote(a) + " " + shell_quote(b));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    const size_t at = r.out.find("relMSE ");
    return at == std::string::npos ? -1.0 : std::stod(r.out.substr(at + 7));
}

// The bound: two independent unbiased estimates A and B of one image differ by
// E[relMSE(A, B)] ≈ Var A + Var B (per-pixel relative variances), and two runs of one method by
// E[relMSE(A1, A2)] ≈ 2 Var A; so R = relMSE(A1, B1) / ½(relMSE(A1, A2) + relMSE(B1, B2)) ≈ 1 +
// bias² / (Var A + Var B). R ≤ 3 lets the noise of these estimates through and fails a bias as
// large as the noise twice over. For the estimate to see all of the error, everything random
// must vary with the seed: the sub-pixel positions too (`mvpl render` rotates their lattice by
// the seed, engine/core/subpixel.h); with fixed positions, DamagedHelmet (its emissive texture
// averaged over few positions) read R 2.99 and MultiUVTest R 4.4, though their means agreed.
// Every model is bounded: the normal-mapped glossy and mirror cells of the NormalTangent tests,
// whose reflection of the sky a point or directional VPL cannot light, are shaded through
// specular chains (light/specular_chain.h; without them R ≈ 8, mean 0.92–0.94).
constexpr double kNoiseRatioBound = 3.0;

fs::path sample_dir() {
    const fs::path dir = fs::temp_directory_path() / "mvpl_sample_models";
    fs::create_directories(dir);
    return dir;
}

// Renders `model` twice with each method (seeds 1 and 2) into dir; expects exit 0, finite
// images and the noise ratio within kNoiseRatioBound; returns the paths {vpl1, pt1}.
std::array<std::string, 2> expect_agrees_with_path_tracer(const fs::path& model,
                                                          const fs::path& dir) {
    const std::string name = model.stem().string();
    SCOPED_TRACE(name);
    const std::string common = shell_quote(model.string()) + " --res 48x48 --quiet ";
    std::string vpl[2], pt[2];
    for (int seed = 0; seed < 2; ++seed) {
        const std::string s = std::to_string(seed + 1);
        vpl[seed] = (dir / (name + "_vpl" + s + ".exr")).string();
        pt[seed] = (dir / (name + "_pt" + s + ".exr")).string();
        const auto r = run_mvpl_gpu("render " + common + "--vpls 512 --seed " + s + " -o " +
                                    shell_quote(vpl[seed]));
        EXPECT_EQ(r.exit_code, 0) << r.err;
        const auto p = run_mvpl("reference " + common + "--spp 16 --seed " + s + " -o " +
                                shell_quote(pt[seed]));
        EXPECT_EQ(p.exit_code, 0) << p.err;
        if (r.exit_code != 0 || p.exit_code != 0) return {};
    }
    const Rgb a = read_exr(vpl[0]).mean(), b = read_exr(pt[0]).mean();
    EXPECT_TRUE(std::isfinite(luminance(a)) && std::isfinite(luminance(b)));
    const double across = rel_mse(vpl[0], pt[0]);
    const double noise = 0.5 * (rel_mse(vpl[0], vpl[1]) + rel_mse(pt[0], pt[1]));
    const double ratio = across / std::max(noise, 1e-12);
    EXPECT_LE(ratio, kNoiseRatioBound) << "relMSE " << across << ", noise " << noise;
    ::testing::Test::RecordProperty(name, std::to_string(ratio));
    std::printf("%-30s VPL/PT mean %.3f, relMSE %.4g, noise %.4g, ratio %.2f\n", name.c_str(),
                luminance(a) / std::max(luminance(b), 1e-30f), across, noise, ratio);
    return {vpl[0], pt[0]};
}

// One test per model, so that the test runner spreads them over its jobs; the material
// extensions' models (UnlitTest, SpecGlossVsMetalRough) are rendered by the test after these.
std::vector<fs::path> models_without_extensions() {
    std::vector<fs::path> out;
    for (const fs::path& model : sample_models()) {
        const std::string name = model.stem().string();
        if (name != "UnlitTest" && name != "SpecGlossVsMetalRough") out.push_back(model);
    }
    return out;
}

class EveryModel : public ::testing::TestWithParam<fs::path> {};

TEST_P(EveryModel, RendersFiniteOnTheGpuAndWithThePathTracer) {
    expect_agrees_with_path_tracer(GetParam(), sample_dir());
}

INSTANTIATE_TEST_SUITE_P(SampleModels, EveryModel, ::testing::ValuesIn(models_without_extensions()),
                         [](const ::testing::TestParamInfo<fs::path>& info) {
                             std::string name = info.param.stem().string();
                             for (char& c : name)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return name;
                         });
// Without ../shared/gltf-samples there are no models, hence no instances.
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(EveryModel);

// KHR_materials_pbrSpecularGlossiness and KHR_materials_unlit (issue 32, item 6): their models
// against the path tracer as above, and UnlitTest's colours. UnlitTest shows its base colours and
// nothing else: every pixel of both images is a mix of black, orange (1, k, 0) and blue (0, k, 1),
// k = 0.2176 (anti-aliased edges), i.e. g = k (r + b) and r + b ≤ 1, to float precision (no
// shading, no noise).
TEST(SampleModels, MaterialExtensionModelsAgreeWithThePathTracer) {
    const fs::path root = fs::path(MVPL_SOURCE_DIR) / ".." / "shared" / "gltf-samples";
    const fs::path unlit = root / "UnlitTest" / "glTF" / "UnlitTest.gltf";
    const fs::path spec_gloss =
        root / "SpecGlossVsMetalRough" / "glTF" / "SpecGlossVsMetalRough.gltf";
    if (!fs::exists(unlit) || !fs::exists(spec_gloss)) GTEST_SKIP() << "no sample models";
    const fs::path dir = sample_dir();
    expect_agrees_with_path_tracer(spec_gloss, dir);
    constexpr float k = 0.217637640824031f;
    for (const std::string& path : expect_agrees_with_path_tracer(unlit, dir)) {
        if (path.empty()) continue;
        const Image image = read_exr(path);
        int coloured = 0;
        for (const Rgb& p : image.pixels()) {
            EXPECT_NEAR(p.g, k * (p.r + p.b), 1e-3f) << path;
            EXPECT_LE(p.r + p.b, 1.0f + 1e-3f) << path;
            coloured += p.r + p.b > 0.999f;
        }
        EXPECT_GT(coloured, 100) << path;  // the two objects fill a good part of the frame
    }
}

}  // namespace
}  // namespace mvpl
