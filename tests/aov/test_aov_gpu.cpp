// The CPU's AOVs (engine/aov/aov_tracer.h) against what the GPU shades: the G-buffers the renderer
// draws at the same sub-pixel positions, averaged as the AOVs are, on the textured, normal-mapped
// scene of assets/textured. Same bound and reasoning as tests/render/test_textured_scene.cpp
// (GBufferResolvesTexturesAndNormalMapsAsTheCpu): 1e-3, the rounding of the two intersection
// computations amplified by the textures' slopes, with pixels where the rasteriser and Embree pick
// different triangles (silhouettes, seams) allowed in 1 of 50.
#include <gtest/gtest.h>

#include "engine/aov/aov_images.h"
#include "engine/core/subpixel.h"
#include "engine/gpu/command_list.h"
#include "engine/gpu/context.h"
#include "engine/light/light_sampler.h"
#include "engine/render/g_buffer_pass.h"
#include "engine/render/scene_geometry.h"
#include "engine/render/vpl_renderer.h"
#include "engine/scene/scene_loader.h"
#include "engine/trace/accel.h"
#include "tests/gpu/gpu_test.h"

namespace mvpl::aov {
namespace {

using AovGpuTest = gpu::testing::GpuTest;

struct Expected4 {
    Rgb albedo{0.0f};
    Vec3 normal{0.0f};
    Vec3 position{0.0f};
};

TEST_F(AovGpuTest, AgreesWithTheGBuffersAtTheRendersPositions) {
    const scene::Scene s = scene::load_scene(MVPL_ASSETS_DIR "/textured/textured.gltf");
    constexpr uint32_t kRes = 32;
    constexpr uint64_t kPositions = 4;
    integrator::Estimate e;
    e.render.width = kRes;
    e.render.height = kRes;
    e.render.subpixel_rotation = subpixel_rotation(9);
    const uint64_t vpls = uint64_t(e.render.batch) * e.render.batches_per_position * kPositions;
    const SubpixelSchedule schedule = render::subpixel_schedule(e.render);
    ASSERT_EQ(schedule.positions_after(vpls), kPositions);

    // The GPU: one G-buffer per position, base colour, normal (on the side the camera sees, as
    // the shading pass flips it) and position summed per pixel.
    const render::SceneGeometry geometry(context(), s);
    render::GBufferPass pass(context(), geometry, kRes, kRes);
    std::vector<Expected4> gpu(kRes * kRes);
    std::vector<int> covered(kRes * kRes, 0);
    for (uint64_t p = 0; p < kPositions; ++p) {
        context().submit_and_wait(
            [&](gpu::CommandList& cmd) { pass.record(cmd, s.camera, schedule.position(p)); });
        const std::vector<render::GBufferTexel> texels = pass.download();
        for (size_t i = 0; i < texels.size(); ++i) {
            const render::GBufferTexel& t = texels[i];
            if (!t.covered) continue;
            const bool flip = !t.front_face && t.double_sided;
            gpu[i].albedo += t.closure.base_color / float(kPositions);
            gpu[i].normal += (flip ? -1.0f : 1.0f) * t.shading_normal / float(kPositions);
            gpu[i].position += t.position / float(kPositions);
            ++covered[i];
        }
    }

    const trace::Accel accel(s);
    const light::LightSampler lights(s);
    const std::vector<ChannelImage> cpu =
        render_aovs({&s, &accel, &lights, &s.camera}, e, vpls,
                    parse_aov_list("albedo,normal,position", "--aov"));
    ASSERT_EQ(cpu.size(), 3u);
    int compared = 0, bad = 0;
    const float scale = glm::length(s.bounds().hi - s.bounds().lo);
    for (size_t i = 0; i < gpu.size(); ++i) {
        if (covered[i] != int(kPositions)) continue;  // a silhouette: the background mixes in
        ++compared;
        float d_albedo = 0.0f, d_normal = 0.0f, d_position = 0.0f;
        for (int c = 0; c < 3; ++c) {
            d_albedo = std::max(d_albedo, std::abs(cpu[0].values[3 * i + c] - gpu[i].albedo[c]));
            d_normal = std::max(d_normal, std::abs(cpu[1].values[3 * i + c] - gpu[i].normal[c]));
            d_position =
                std::max(d_position, std::abs(cpu[2].values[3 * i + c] - gpu[i].position[c]));
        }
        if ((d_albedo > 1e-3f || d_normal > 1e-3f || d_position > 1e-4f * scale) && bad++ < 8) {
            ADD_FAILURE() << "pixel " << i % kRes << "," << i / kRes << ": albedo " << d_albedo
                          << ", normal " << d_normal << ", position " << d_position;
        }
    }
    EXPECT_GT(compared, int(kRes * kRes) / 2);
    EXPECT_LE(bad, compared / 50);
}

}  // namespace
}  // namespace mvpl::aov
