#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>
#include <string>

#include "engine/core/image.h"
#include "engine/gpu/context.h"
#include "engine/render/vpl_renderer.h"
#include "engine/scene/scene_loader.h"
#include "tests/gpu/gpu_test.h"

namespace mvpl::render {
namespace {

using CornellBoxTest = gpu::testing::GpuTest;

// 64 hand-placed VPLs in the Cornell box (millimetres): 16 Area VPLs on a 4×4 grid over the
// luminaire, each with a sixteenth of its radiance × area, and 48 diffuse Surface VPLs on the
// floor, ceiling and side walls with a plausible one-bounce power.
std::vector<light::Vpl> cornell_vpls(const scene::Scene& scene) {
    std::vector<light::Vpl> vpls;
    Rgb le(0.0f);
    for (const scene::Material& m : scene.materials)
        le = glm::max(le, m.emission());
    const float light_area = 130.0f * 105.0f;
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
            light::Vpl v;
            v.type = light::VplType::Area;
            v.position = Vec3(213.0f + 130.0f * (i + 0.5f) / 4.0f, 548.2f,
                              227.0f + 105.0f * (j + 0.5f) / 4.0f);
            v.normal = Vec3(0, -1, 0);
            v.power = le * light_area / 16.0f;
            vpls.push_back(v);
        }
    }
    struct Wall {
        Vec3 origin, u, v, normal;
        Rgb albedo;
    };
    const Wall walls[] = {
        {{50, 0, 50}, {450, 0, 0}, {0, 0, 450}, {0, 1, 0}, Rgb(0.725f, 0.71f, 0.68f)},
        {{50, 548.7f, 50}, {450, 0, 0}, {0, 0, 450}, {0, -1, 0}, Rgb(0.725f, 0.71f, 0.68f)},
        {{0.5f, 50, 50}, {0, 450, 0}, {0, 0, 450}, {1, 0, 0}, Rgb(0.63f, 0.065f, 0.05f)},
        {{549.5f, 50, 50}, {0, 450, 0}, {0, 0, 450}, {-1, 0, 0}, Rgb(0.14f, 0.45f, 0.091f)},
    };
    for (const Wall& w : walls) {
        for (int i = 0; i < 4; ++i) {
            for (int j = 0; j < 3; ++j) {
                light::Vpl v;
                v.type = light::VplType::Surface;
                v.position = w.origin + w.u * ((i + 0.5f) / 4.0f) + w.v * ((j + 0.5f) / 3.0f);
                v.normal = v.shading_normal = w.normal;
                v.wi = w.normal;
                v.closure.base_color = w.albedo;
                v.closure.metallic = 0.0f;
                v.closure.specular = 0.0f;
                v.power = Rgb(2.0e4f);
                v.path_length = 1;
                vpls.push_back(v);
            }
        }
    }
    return vpls;
}

TEST_F(CornellBoxTest, RendersSixtyFourVplsAndReportsPassTimes) {
    const scene::Scene scene = scene::load_scene(MVPL_ASSETS_DIR "/cornell-box/cbox.gltf");
    const std::vector<light::Vpl> vpls = cornell_vpls(scene);
    ASSERT_EQ(vpls.size(), 64u);
    VplRenderer renderer(context(), scene);
    RenderOptions options;
    options.width = options.height = 256;
    options.shadow_resolution = 256;
    options.batch = 32;
    options.clamp = 0.01f;
    RenderTimings timings;
    const Image image = renderer.render({vpls}, options, &timings);

    bool finite = true;
    for (const Rgb& p : image.pixels())
        finite = finite && is_finite(p) && p.r >= 0.0f && p.g >= 0.0f && p.b >= 0.0f;
    EXPECT_TRUE(finite);
    const Rgb mean = image.mean();
    EXPECT_GT(mean.r, mean.b) << "the luminaire is orange: red dominates";
    EXPECT_GT(mean.b, 0.0f);
    // The emitted radiance is added once: the luminaire's pixels show it (row 0 at the top).
    EXPECT_GT(image.at(128, 2).r + image.at(128, 4).r + image.at(128, 6).r, 0.0f);
    EXPECT_EQ(timings.batches, 2u);
    EXPECT_GT(timings.shading_ms, 0.0);
    std::cout << "cbox 256x256, 64 VPLs, 256^2 shadow faces, batch 32: g-buffer "
              << timings.g_buffer_ms << " ms, shadow " << timings.shadow_ms << " ms, shading "
              << timings.shading_ms << " ms, GPU total " << timings.total_ms << " ms, wall "
              << timings.wall_ms << " ms; mean " << mean.r << " " << mean.g << " " << mean.b
              << "\n";
    RecordProperty("g_buffer_ms", std::to_string(timings.g_buffer_ms));
    RecordProperty("shadow_ms", std::to_string(timings.shadow_ms));
    RecordProperty("shading_ms", std::to_string(timings.shading_ms));
    if (std::getenv("MVPL_RENDER_BENCH")) {
        for (uint32_t batch : {8u, 16u, 32u, 64u}) {
            for (bool shadows : {true, false}) {
                options.batch = batch;
                options.shadows = shadows;
                renderer.render({vpls}, options, &timings);
                std::cout << "batch " << batch << " shadows " << shadows << ": g-buffer "
                          << timings.g_buffer_ms << " shadow " << timings.shadow_ms << " shading "
                          << timings.shading_ms << " wall " << timings.wall_ms << "\n";
            }
        }
    }
    if (const char* out = std::getenv("MVPL_RENDER_TEST_OUTPUT")) {
        write_image(image, std::string(out) + "/cbox-64-vpls.exr");
        write_image(image, std::string(out) + "/cbox-64-vpls.png");
    }
}

}  // namespace
}  // namespace mvpl::render
