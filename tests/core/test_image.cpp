#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "engine/core/error.h"
#include "engine/core/image.h"
#include "engine/core/image_metrics.h"

namespace mvpl {
namespace {

std::string temp_path(const std::string& name) {
    return (std::filesystem::temp_directory_path() /
            ("mvpl_test_" + std::to_string(::getpid()) + "_" + name))
        .string();
}

TEST(Image, ExrRoundTripIsExactForFloats) {
    Image image(7, 5);
    for (int y = 0; y < 5; ++y) {
        for (int x = 0; x < 7; ++x)
            image.at(x, y) = Rgb(x * 0.1f, y * 1e3f, 1e-7f * (x + 1) * (y + 1));
    }
    const std::string path = temp_path("roundtrip.exr");
    write_exr(image, path);
    const Image back = read_exr(path);
    ASSERT_EQ(back.width(), 7);
    ASSERT_EQ(back.height(), 5);
    for (size_t i = 0; i < image.pixels().size(); ++i)
        EXPECT_EQ(back.pixels()[i], image.pixels()[i]);
    std::filesystem::remove(path);
}

TEST(Image, ReadsTheHalfFloatMitsubaReference) {
    const Image ref = read_exr(MVPL_ASSETS_DIR "/cornell-box/ref-cbox-d6-4096.exr");
    ASSERT_EQ(ref.width(), 256);
    ASSERT_EQ(ref.height(), 256);
    // The mean that the reference folder's README gives.
    const Rgb m = ref.mean();
    EXPECT_NEAR(m.r, 0.21174f, 2e-4f);
    EXPECT_NEAR(m.g, 0.10294f, 2e-4f);
    EXPECT_NEAR(m.b, 0.02580f, 2e-4f);
}

TEST(Image, BadExrIsAnInputErrorNamingTheFile) {
    const std::string path = temp_path("not.exr");
    FILE* f = std::fopen(path.c_str(), "wb");
    std::fputs("this is not an EXR file", f);
    std::fclose(f);
    try {
        read_exr(path);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(path, 0), 0u) << e.what();
    }
    std::filesystem::remove(path);
}

TEST(Image, PngWriteAndSrgbCurve) {
    EXPECT_FLOAT_EQ(linear_to_srgb(0.0f), 0.0f);
    EXPECT_FLOAT_EQ(linear_to_srgb(1.0f), 1.0f);
    EXPECT_FLOAT_EQ(linear_to_srgb(std::nanf("")), 0.0f);
    for (float v : {0.001f, 0.01f, 0.2f, 0.5f, 0.9f})
        EXPECT_NEAR(srgb_to_linear(linear_to_srgb(v)), v, 1e-5f);
    Image image(4, 4);
    const std::string path = temp_path("out.png");
    write_image(image, path);
    EXPECT_GT(std::filesystem::file_size(path), 0u);
    std::filesystem::remove(path);
    EXPECT_THROW(write_image(image, temp_path("out.bmp")), UsageError);
}

TEST(ImageMetrics, KnownValues) {
    Image a(2, 1), r(2, 1);
    r.at(0, 0) = Rgb(1.0f);
    r.at(1, 0) = Rgb(0.0f);
    a.at(0, 0) = Rgb(1.1f);
    a.at(1, 0) = Rgb(0.1f);
    const ImageError e = compare_images(a, r);
    // ((0.01 / 1.01) + (0.01 / 0.01)) / 2
    EXPECT_NEAR(e.rel_mse, (0.01 / 1.01 + 1.0) / 2.0, 1e-6);
    EXPECT_NEAR(e.rmse, 0.1, 1e-6);
    EXPECT_NEAR(e.mean_abs, 0.1, 1e-6);
    EXPECT_NEAR(e.mean_ratio.x, 1.2, 1e-6);
    EXPECT_THROW(compare_images(a, Image(3, 1)), UsageError);
}

TEST(ImageMetrics, BlockAverage) {
    Image a(4, 2);
    for (int x = 0; x < 4; ++x)
        a.at(x, 0) = a.at(x, 1) = Rgb(float(x));
    const Image b = block_average(a, 2);
    ASSERT_EQ(b.width(), 2);
    ASSERT_EQ(b.height(), 1);
    EXPECT_FLOAT_EQ(b.at(0, 0).r, 0.5f);
    EXPECT_FLOAT_EQ(b.at(1, 0).r, 2.5f);
}

}  // namespace
}  // namespace mvpl
