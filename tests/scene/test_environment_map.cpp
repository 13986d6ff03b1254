// Environment maps (issue 12): reading them (and refusing bad ones with the file and the reason),
// their orientation (the glTF Sample Viewer's), and importance sampling that pays: next-event
// estimation of a map that is black but for a small bright region has far lower variance than
// uniform sampling of the sphere, with the same mean.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include "engine/core/error.h"
#include "engine/core/image.h"
#include "engine/core/rng.h"
#include "engine/core/sampling.h"
#include "engine/light/light_sampler.h"
#include "engine/scene/environment_map.h"
#include "tests/support/scene_builder.h"

namespace mvpl::scene {
namespace {

namespace fs = std::filesystem;

fs::path temp_path(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / "mvpl_environment_map_test";
    fs::create_directories(dir);
    return dir / name;
}

std::string exr_file(const std::string& name, const Image& image) {
    const fs::path p = temp_path(name);
    write_exr(image, p.string());
    return p.string();
}

// The one-line message of the InputError that loading `path` throws, or "" if it loads.
std::string load_error(const std::string& path) {
    try {
        load_environment_map(path);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(EnvironmentMap, BadMapsAreRefusedWithTheFileAndWhatIsWrong) {
    Image good(8, 4);
    for (Rgb& t : good.pixels())
        t = Rgb(0.5f);
    const std::string ok = exr_file("ok.exr", good);
    EXPECT_EQ(load_error(ok), "");
    EXPECT_EQ(load_environment_map(ok)->width, 8);

    const std::string missing = temp_path("missing.hdr").string();
    EXPECT_NE(load_error(missing).find(missing + ": no such environment map"), std::string::npos);
    const std::string png = temp_path("map.png").string();
    write_png(good, png);
    EXPECT_NE(load_error(png).find(".hdr or .exr"), std::string::npos) << load_error(png);

    const std::string square = exr_file("square.exr", Image(4, 4));
    EXPECT_NE(load_error(square).find("twice as wide as high"), std::string::npos);

    const float bad[] = {std::numeric_limits<float>::quiet_NaN(), -1.0f,
                         std::numeric_limits<float>::infinity()};
    const char* names[] = {"NaN", "negative", "infinite"};
    for (int i = 0; i < 3; ++i) {
        Image image = good;
        image.at(3, 1).g = bad[i];
        const std::string path = exr_file(std::string("bad") + names[i] + ".exr", image);
        EXPECT_NE(load_error(path).find(path + ": texel (3, 1) is " + names[i]), std::string::npos)
            << load_error(path);
    }

    // A Radiance header that promises 20000 × 10000 texels: refused before decoding.
    const fs::path huge = temp_path("huge.hdr");
    std::ofstream(huge) << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 10000 +X 20000\n";
    EXPECT_NE(load_error(huge.string()).find("too large for memory"), std::string::npos)
        << load_error(huge.string());
    const fs::path garbage = temp_path("garbage.hdr");
    std::ofstream(garbage) << "not an image";
    EXPECT_NE(load_error(garbage.string()).find("cannot decode"), std::string::npos);
}

// An 8 × 4 map whose texel (x, y) has the value x + 10 y: where a direction lands says which
// texel it reads.
Environment numbered_environment(float rotation_degrees = 0.0f) {
    auto map = std::make_shared<EnvironmentMap>();
    map->width = 8;
    map->height = 4;
    for (int y = 0; y < 4; ++y) {
        for (int x = 0; x < 8; ++x)
            map->texels.push_back(Rgb(float(x + 10 * y)));
    }
    Environment e;
    e.radiance = Rgb(1.0f);
    e.map = map;
    e.rotation = rotation_degrees * kPi / 180.0f;
    return e;
}

float texel_seen(const Environment& e, const Vec3& w) {
    return e.lookup(glm::normalize(w)).r;
}

TEST(EnvironmentMap, OrientationIsTheSampleViewers) {
    const Environment e = numbered_environment();
    // The centre column faces +X, three quarters across +Z, a quarter across −Z, the left edge −X;
    // the top row is up. Just above and below the horizon: rows 1 and 2; each direction a
    // little off the column boundary it would otherwise sit on.
    EXPECT_EQ(texel_seen(e, Vec3(1.0f, 0.1f, 0.001f)), 4.0f + 10.0f);
    EXPECT_EQ(texel_seen(e, Vec3(-0.001f, 0.1f, 1.0f)), 6.0f + 10.0f);
    EXPECT_EQ(texel_seen(e, Vec3(0.001f, -0.1f, -1.0f)), 2.0f + 20.0f);
    EXPECT_EQ(texel_seen(e, Vec3(-1.0f, -0.1f, -0.001f)), 0.0f + 20.0f);
    EXPECT_EQ(texel_seen(e, Vec3(0.0f, 1.0f, 0.0f)) < 10.0f, true);  // the top row
    // Turned by 90° about +Y, what faced +X faces −Z (glTF's right-handed rotation).
    const Environment turned = numbered_environment(90.0f);
    EXPECT_EQ(texel_seen(turned, Vec3(0.001f, 0.1f, -1.0f)), 4.0f + 10.0f);
    // uv_to_direction inverts direction_to_uv.
    Rng rng(7, 1);
    for (int i = 0; i < 100; ++i) {
        const Vec2 uv(rng.next_float(), 0.05f + 0.9f * rng.next_float());
        const Vec2 back = turned.direction_to_uv(turned.uv_to_direction(uv));
        EXPECT_NEAR(back.x, uv.x, 1e-4f);
        EXPECT_NEAR(back.y, uv.y, 1e-4f);
    }
}

// Irradiance at an upward-facing point from a map that is black but for a bright patch
// (2 × 2 texels of 64 × 32, radiance 10⁴) over a dim sky (10⁻²): estimated by the light
// sampler's next-event estimation (what the path tracer does) and by uniform sphere sampling.
TEST(EnvironmentMap, ImportanceSamplingPays) {
    auto map = std::make_shared<EnvironmentMap>();
    map->width = 64;
    map->height = 32;
    map->texels.assign(64 * 32, Rgb(0.01f));
    for (int y = 8; y < 10; ++y) {
        for (int x = 40; x < 42; ++x)
            map->texels[size_t(y) * 64 + size_t(x)] = Rgb(1e4f);
    }
    Scene scene;
    scene.materials = {test::diffuse_material(Rgb(0.5f))};
    scene.meshes.push_back(test::make_quad(Vec3(-1, 0, -1), Vec3(0, 0, 2), Vec3(2, 0, 0), 0));
    scene.environment.radiance = Rgb(1.0f);
    scene.environment.map = map;
    const light::LightSampler lights(scene);
    const Vec3 n(0.0f, 1.0f, 0.0f);
    constexpr int kRuns = 64, kSamples = 1024;
    std::vector<double> nee, uniform;
    Rng rng(11, 2);
    for (int r = 0; r < kRuns; ++r) {
        double a = 0.0, b = 0.0;
        for (int s = 0; s < kSamples; ++s) {
            const float u_pick = rng.next_float();
            const Vec2 u(rng.next_float(), rng.next_float());
            if (const auto ls = lights.sample_li(Vec3(0.0f), u_pick, u)) {
                a += double(ls->li.g) * std::max(0.0f, glm::dot(n, ls->wi)) / double(ls->pdf);
                // What the path tracer's MIS weights against: the same density for the same
                // direction.
                EXPECT_NEAR(lights.pdf_environment(ls->wi), ls->pdf, 1e-3f * ls->pdf);
            }
            const Vec3 w = sample_uniform_sphere(Vec2(rng.next_float(), rng.next_float()));
            b += double(scene.environment.lookup(w).g) * std::max(0.0f, glm::dot(n, w)) * 4.0 *
                 double(kPi);
        }
        nee.push_back(a / kSamples);
        uniform.push_back(b / kSamples);
    }
    const auto stats = [](const std::vector<double>& v) {
        double mean = 0.0, var = 0.0;
        for (double x : v)
            mean += x / double(v.size());
        for (double x : v)
            var += (x - mean) * (x - mean) / double(v.size() - 1);
        return std::pair{mean, var};
    };
    const auto [mean_nee, var_nee] = stats(nee);
    const auto [mean_uniform, var_uniform] = stats(uniform);
    EXPECT_GE(var_uniform, 10.0 * var_nee) << var_uniform << " against " << var_nee;
    const double se = std::sqrt((var_nee + var_uniform) / double(kRuns));
    EXPECT_LT(std::abs(mean_nee - mean_uniform), 4.0 * se) << mean_nee << " vs " << mean_uniform;
    RecordProperty("variance_ratio", std::to_string(var_uniform / var_nee));
}

}  // namespace
}  // namespace mvpl::scene
