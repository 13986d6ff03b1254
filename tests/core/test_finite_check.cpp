#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>

#include "engine/core/finite_check.h"

namespace mvpl {
namespace {

TEST(FiniteCheck, CountsNonFinitePixelsAndFindsTheFirstInRowMajorOrder) {
    Image image(5, 4);
    for (Rgb& c : image.pixels())
        c = Rgb(1e30f, 0.0f, -1e-30f);  // huge, zero and denormal-ish values are finite
    EXPECT_EQ(find_non_finite(image).pixels, 0u);
    EXPECT_NO_THROW(require_finite(image, "test"));

    image.at(3, 2)[1] = std::numeric_limits<float>::infinity();
    image.at(1, 3)[0] = std::numeric_limits<float>::quiet_NaN();
    image.at(4, 1)[2] = -std::numeric_limits<float>::infinity();
    const NonFiniteReport report = find_non_finite(image);
    EXPECT_EQ(report.pixels, 3u);
    EXPECT_EQ(report.first_x, 4);
    EXPECT_EQ(report.first_y, 1);
    try {
        require_finite(image, "resolve");
        ADD_FAILURE() << "no exception";
    } catch (const NonFiniteError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind("resolve: 3 non-finite pixels, the first at (4, 1)", 0), 0u) << what;
    }
}

TEST(FiniteCheck, WriteImageRefusesANonFiniteImageAndWritesNothing) {
    Image image(3, 3);
    image.at(2, 0) = Rgb(0.5f, std::numeric_limits<float>::quiet_NaN(), 0.5f);
    for (const char* name : {"nan.exr", "nan.png"}) {
        const std::filesystem::path path = std::filesystem::temp_directory_path() / name;
        std::filesystem::remove(path);
        EXPECT_THROW(write_image(image, path.string()), NonFiniteError);
        EXPECT_FALSE(std::filesystem::exists(path)) << path;
    }
}

}  // namespace
}  // namespace mvpl
