#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <span>
#include <vector>

#include "engine/gpu/buffer.h"
#include "engine/gpu/command_list.h"
#include "engine/gpu/compute_pipeline.h"
#include "engine/gpu/context.h"
#include "engine/gpu/gpu_error.h"
#include "engine/gpu/image.h"
#include "engine/gpu/shader_compiler.h"
#include "tests/gpu/gpu_test.h"

namespace mvpl::gpu {
namespace {

using ImageTest = testing::GpuTest;

constexpr uint32_t kCubes = 3;  // B VPLs in a shadow batch
constexpr uint32_t kFace = 16;

float layer_value(uint32_t layer) {
    return 0.25f + 1.5f * float(layer);
}

Image make_shadow_cubes(Context& context, Format format, ImageUsage usage) {
    ImageDesc desc;
    desc.width = kFace;
    desc.height = kFace;
    desc.layers = 6 * kCubes;
    desc.format = format;
    desc.usage = usage;
    desc.cube = true;
    return Image(context, desc, "shadow cubes");
}

// Clears every layer to its own value, one clear per layer as the shadow pass fills faces.
void clear_layers(Context& context, Image& cubes) {
    context.submit_and_wait([&](CommandList& cmd) {
        for (uint32_t layer = 0; layer < cubes.layers(); ++layer) {
            if (is_depth(cubes.format()))
                cmd.clear_depth(cubes, layer_value(layer) / 100.0f, layer, 1);
            else
                cmd.clear_color(cubes, {layer_value(layer), 0.0f, 0.0f, 0.0f}, layer, 1);
        }
    });
}

TEST_F(ImageTest, Rgba32fRoundTripIsExact) {
    ImageDesc desc;
    desc.width = 37;  // odd sizes: no row padding may creep in
    desc.height = 23;
    desc.format = Format::rgba32_float;
    desc.usage = ImageUsage::sampled | ImageUsage::storage;
    Image image(context(), desc, "rgba32f");
    std::vector<float> pixels(size_t(desc.width) * desc.height * 4);
    for (size_t i = 0; i < pixels.size(); ++i) {
        pixels[i] = (i % 3 == 0 ? -1.0f : 1.0f) * std::ldexp(float(i) + 0.125f, int(i % 41) - 20);
    }
    pixels[5] = std::numeric_limits<float>::infinity();
    pixels[6] = 1e-40f;  // denormal: a copy must not flush it
    image.upload(pixels);
    const std::vector<float> back = image.download_as<float>();
    ASSERT_EQ(back.size(), pixels.size());
    EXPECT_EQ(std::memcmp(back.data(), pixels.data(), pixels.size() * sizeof(float)), 0);
    EXPECT_NE(image.view(), nullptr);
    EXPECT_EQ(image.layer_view(0), nullptr) << "no attachment usage, no per-layer views";
}

TEST_F(ImageTest, CubeMapArrayLayersAreClearedSeparately) {
    Image cubes = make_shadow_cubes(context(), Format::r32_float,
                                    ImageUsage::sampled | ImageUsage::color_attachment);
    ASSERT_EQ(cubes.layers(), 6 * kCubes);
    EXPECT_NE(cubes.view(), nullptr);
    for (uint32_t layer = 0; layer < cubes.layers(); ++layer)
        EXPECT_NE(cubes.layer_view(layer), nullptr);
    clear_layers(context(), cubes);
    const std::vector<float> texels = cubes.download_as<float>(0, cubes.layers());
    ASSERT_EQ(texels.size(), size_t(kFace) * kFace * cubes.layers());
    for (uint32_t layer = 0; layer < cubes.layers(); ++layer) {
        for (uint32_t i = 0; i < kFace * kFace; ++i) {
            ASSERT_EQ(texels[layer * kFace * kFace + i], layer_value(layer)) << "layer " << layer;
        }
    }
    // One layer alone, in the middle of the array.
    const std::vector<float> layer7 = cubes.download_as<float>(7, 1);
    EXPECT_EQ(layer7.front(), layer_value(7));
    EXPECT_EQ(layer7.back(), layer_value(7));
}

TEST_F(ImageTest, CubeMapArrayIsSampledByDirectionAndCube) {
    Image cubes = make_shadow_cubes(context(), Format::r32_float,
                                    ImageUsage::sampled | ImageUsage::color_attachment);
    clear_layers(context(), cubes);
    Buffer values(context(), 6 * kCubes * sizeof(float), BufferUsage::storage,
                  MemoryLocation::readback, "face values");
    const ComputePipeline pipeline(
        context(), compile_embedded_shader("test/sample_cube_array.comp"),
        {{BindingType::sampled_image, BindingType::storage_buffer}, 0}, "sample cube array");
    context().submit_and_wait([&](CommandList& cmd) {
        cmd.dispatch(pipeline, {&cubes, &values}, {}, kCubes);
    });
    const std::vector<float> sampled = values.download<float>(6 * kCubes);
    for (uint32_t layer = 0; layer < 6 * kCubes; ++layer) {
        EXPECT_EQ(sampled[layer], layer_value(layer))
            << "cube " << layer / 6 << " face " << layer % 6;
    }
}

TEST_F(ImageTest, DepthCubeMapArrayLayersAreClearedSeparately) {
    Image cubes = make_shadow_cubes(context(), Format::d32_float,
                                    ImageUsage::sampled | ImageUsage::depth_attachment);
    clear_layers(context(), cubes);
    const std::vector<float> texels = cubes.download_as<float>(0, cubes.layers());
    for (uint32_t layer = 0; layer < cubes.layers(); ++layer) {
        EXPECT_EQ(texels[layer * kFace * kFace], layer_value(layer) / 100.0f) << "layer " << layer;
        EXPECT_EQ(texels[(layer + 1) * kFace * kFace - 1], layer_value(layer) / 100.0f);
    }
}

TEST_F(ImageTest, LayeredUploadWritesOnlyItsLayers) {
    ImageDesc desc;
    desc.width = 8;
    desc.height = 4;
    desc.layers = 4;
    desc.format = Format::r32_float;
    Image image(context(), desc, "layers");
    context().submit_and_wait([&](CommandList& cmd) { cmd.clear_color(image, {-1, 0, 0, 0}); });
    image.upload(std::vector<float>(2 * 8 * 4, 5.0f), 1, 2);
    const std::vector<float> all = image.download_as<float>(0, 4);
    EXPECT_EQ(all[0], -1.0f);
    EXPECT_EQ(all[32], 5.0f);
    EXPECT_EQ(all[95], 5.0f);
    EXPECT_EQ(all[96], -1.0f);
    EXPECT_THROW(image.upload(std::vector<float>(8 * 4, 1.0f), 4, 1), GpuError);
    EXPECT_THROW(image.upload(std::vector<float>(7, 1.0f), 0, 1), GpuError);
}

// Uploads in a row through one buffer (how the G-buffer pass uploads a scene's textures): each
// image gets its own texels, a smaller image after a larger one included, and a buffer too small
// for the texels is refused.
TEST_F(ImageTest, UploadsThroughOneBufferEachKeepTheirTexels) {
    ImageDesc large;
    large.width = 16;
    large.height = 8;
    large.format = Format::r32_float;
    ImageDesc small = large;
    small.width = 4;
    small.height = 2;
    Image a(context(), large, "a");
    Image b(context(), small, "b");
    Buffer staging(context(), a.layer_bytes(), BufferUsage::none, MemoryLocation::upload, "up");
    std::vector<float> texels_a(16 * 8), texels_b(4 * 2);
    for (size_t i = 0; i < texels_a.size(); ++i)
        texels_a[i] = float(i);
    for (size_t i = 0; i < texels_b.size(); ++i)
        texels_b[i] = -float(i) - 1.0f;
    a.upload(std::as_bytes(std::span(texels_a)), staging);
    b.upload(std::as_bytes(std::span(texels_b)), staging);
    EXPECT_EQ(a.download_as<float>(), texels_a);
    EXPECT_EQ(b.download_as<float>(), texels_b);
    Buffer too_small(context(), b.layer_bytes(), BufferUsage::none, MemoryLocation::upload, "up");
    EXPECT_THROW(a.upload(std::as_bytes(std::span(texels_a)), too_small), GpuError);
}

TEST_F(ImageTest, BadDescriptionsAreErrors) {
    ImageDesc cube;
    cube.width = 16;
    cube.height = 8;
    cube.layers = 6;
    cube.format = Format::r32_float;
    cube.cube = true;
    EXPECT_THROW(Image(context(), cube, "not square"), GpuError);
    cube.height = 16;
    cube.layers = 7;
    EXPECT_THROW(Image(context(), cube, "not whole cubes"), GpuError);
    ImageDesc huge;
    huge.width = context().device_info().limits.max_image_dimension_2d + 1;
    EXPECT_THROW(Image(context(), huge, "too wide"), GpuError);
}

}  // namespace
}  // namespace mvpl::gpu
