#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

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

// write_images is all-or-none by itself (the CLI also checks outputs up front): when one target
// cannot be written, no target appears, no temporary is left, and an existing file keeps its
// content.
TEST(Image, SeveralTargetsAreWrittenAllOrNone) {
    namespace fs = std::filesystem;
    const fs::path dir =
        fs::temp_directory_path() / ("mvpl_all_or_none_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    Image image(8, 4);
    image.at(3, 2) = Rgb(0.5f, 0.25f, 1.0f);
    const std::string exr = (dir / "a.exr").string();
    const std::string png = (dir / "b.png").string();
    {
        std::FILE* f = std::fopen(png.c_str(), "wb");
        ASSERT_NE(f, nullptr);
        std::fputs("old", f);
        std::fclose(f);
    }
    const std::string missing = (dir / "no" / "c.png").string();
    try {
        write_images(image, {exr, png, missing});
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(exr));
    EXPECT_EQ(fs::file_size(png), 3u);
    size_t files = 0;
    for ([[maybe_unused]] const fs::directory_entry& e : fs::directory_iterator(dir))
        ++files;
    EXPECT_EQ(files, 1u);
    // And when all can be written, all are, replacing the old file.
    write_images(image, {exr, png});
    EXPECT_EQ(read_exr(exr).at(3, 2), image.at(3, 2));
    EXPECT_GT(fs::file_size(png), 3u);
    // With the permissions a plain create gives (the temporary was private).
    const mode_t mask = umask(0);
    umask(mask);
    EXPECT_EQ(fs::status(exr).permissions() & fs::perms::all, fs::perms(0666 & ~mask));
    fs::remove_all(dir);
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

// `mvpl compare --region`: the rectangle's pixels, row by row, and nothing outside the image.
TEST(ImageMetrics, CropTakesTheRectangle) {
    Image a(4, 3);
    for (int y = 0; y < 3; ++y) {
        for (int x = 0; x < 4; ++x)
            a.at(x, y) = Rgb(float(10 * y + x));
    }
    const Image c = crop(a, 1, 1, 2, 2);
    ASSERT_EQ(c.width(), 2);
    ASSERT_EQ(c.height(), 2);
    EXPECT_FLOAT_EQ(c.at(0, 0).r, 11.0f);
    EXPECT_FLOAT_EQ(c.at(1, 1).r, 22.0f);
    EXPECT_EQ(crop(a, 0, 0, 4, 3).at(3, 2).r, 23.0f);
    EXPECT_THROW(crop(a, 3, 0, 2, 1), UsageError);
    EXPECT_THROW(crop(a, 0, 0, 0, 1), UsageError);
    EXPECT_THROW(crop(a, -1, 0, 1, 1), UsageError);
}

}  // namespace
}  // namespace mvpl
