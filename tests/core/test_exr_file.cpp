// EXR files with extra channels and header attributes (engine/core/exr_file.h): what is written
// reads back exactly, every EXR carries the Rec. 709 chromaticities, bad layers are refused.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "engine/core/exr_file.h"
#include "engine/core/image.h"

namespace mvpl {
namespace {

std::string temp_path(const std::string& name) {
    return (std::filesystem::temp_directory_path() /
            ("mvpl_test_exr_" + std::to_string(::getpid()) + "_" + name))
        .string();
}

Image ramp(int w, int h) {
    Image image(w, h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x)
            image.at(x, y) = Rgb(float(x), float(y), 0.5f);
    }
    return image;
}

ChannelImage layer(const std::string& name, std::vector<std::string> channels, int w, int h) {
    ChannelImage l{name, std::move(channels), w, h, {}};
    for (size_t i = 0; i < size_t(w) * size_t(h) * l.channels.size(); ++i)
        l.values.push_back(0.25f * float(i) - 3.0f);
    return l;
}

TEST(ExrFile, ChannelsAndAttributesReadBackExactly) {
    const int w = 5, h = 3;
    ExrExtras extras;
    extras.layers.push_back(layer("normal", {"N.X", "N.Y", "N.Z"}, w, h));
    extras.layers.push_back(layer("depth", {"Z"}, w, h));
    extras.attributes = {{"mvpl/commandLine", std::string("mvpl render 'a b.gltf'")},
                         {"mvpl/spp", 64},
                         {"mvpl/wallSeconds", 1.25}};
    const std::string path = temp_path("extras.exr");
    write_images(ramp(w, h), {path}, 0.0f, extras);
    const ExrContents back = read_exr_file(path);
    EXPECT_EQ(back.width, w);
    EXPECT_EQ(back.height, h);
    for (const char* name : {"R", "G", "B", "N.X", "N.Y", "N.Z", "Z"})
        ASSERT_NE(back.channel(name), nullptr) << name;
    EXPECT_EQ(back.channels.size(), 7u);
    for (const ChannelImage& l : extras.layers) {
        const size_t n = l.channels.size();
        for (size_t c = 0; c < n; ++c) {
            const std::vector<float>& v = *back.channel(l.channels[c]);
            for (size_t p = 0; p < size_t(w * h); ++p)
                EXPECT_EQ(v[p], l.values[p * n + c]) << l.channels[c] << " " << p;
        }
    }
    EXPECT_EQ((*back.channel("R"))[7], 2.0f);  // pixel (2, 1)
    EXPECT_EQ(back.attribute("mvpl/commandLine"), "mvpl render 'a b.gltf'");
    EXPECT_EQ(back.attribute("mvpl/spp"), "64");
    EXPECT_EQ(std::atof(back.attribute("mvpl/wallSeconds").c_str()), 1.25);
    std::filesystem::remove(path);
}

// ITU-R BT.709's primaries and D65's white point, as CIE xy, on an EXR written without extras.
TEST(ExrFile, EveryExrCarriesTheRec709Chromaticities) {
    const std::string path = temp_path("plain.exr");
    write_exr(ramp(2, 2), path);
    const ExrContents back = read_exr_file(path);
    ASSERT_TRUE(back.has_attribute("chromaticities"));
    const std::string text = back.attribute("chromaticities");
    float v[8];
    ASSERT_EQ(std::sscanf(text.c_str(), "R %f %f G %f %f B %f %f W %f %f", &v[0], &v[1], &v[2],
                          &v[3], &v[4], &v[5], &v[6], &v[7]),
              8)
        << text;
    const float expected[8] = {0.64f, 0.33f, 0.30f, 0.60f, 0.15f, 0.06f, 0.3127f, 0.3290f};
    for (int i = 0; i < 8; ++i)
        EXPECT_FLOAT_EQ(v[i], expected[i]) << i;
    std::filesystem::remove(path);
}

TEST(ExrFile, RefusesALayerOfAnotherSizeOrARepeatedChannel) {
    const std::string path = temp_path("bad.exr");
    ExrExtras wrong_size;
    wrong_size.layers.push_back(layer("albedo", {"albedo.R"}, 3, 2));
    EXPECT_THROW(write_exr_file(ramp(2, 2), wrong_size, path), std::invalid_argument);
    ExrExtras repeated;
    repeated.layers.push_back(layer("red", {"R"}, 2, 2));
    EXPECT_THROW(write_exr_file(ramp(2, 2), repeated, path), std::invalid_argument);
    std::filesystem::remove(path);
}

TEST(ExrFile, ANonFiniteAovIsNotWritten) {
    const std::string path = temp_path("nan.exr");
    ExrExtras extras;
    extras.layers.push_back(layer("depth", {"Z"}, 2, 2));
    extras.layers[0].values[3] = std::nanf("");
    EXPECT_ANY_THROW(write_images(ramp(2, 2), {path}, 0.0f, extras));
    EXPECT_FALSE(std::filesystem::exists(path));
}

}  // namespace
}  // namespace mvpl
