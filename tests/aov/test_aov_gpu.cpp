// The CPU's AOVs (engine/aov/aov_tracer.h) against what the GPU shades: at each of the render's
// sub-pixel positions, the G-buffer it draws or, for a pixel its specular chain continues, the
// chain layer's receiver record (engine/render/chain_layer.h), averaged as the AOVs are. On the
// textured, normal-mapped scene of assets/textured and the glossy scene of assets/glossy. Same
// bound and reasoning as tests/render/test_textured_scene.cpp
// (GBufferResolvesTexturesAndNormalMapsAsTheCpu): 1e-3, the rounding of the two intersection
// computations amplified by the textures' slopes, with pixels where the rasteriser and Embree pick
// different triangles (silhouettes, seams) allowed in 1 of 50.
#include <gtest/gtest.h>

#include <cstring>
#include <sstream>

#include "engine/aov/aov_images.h"
#include "engine/core/subpixel.h"
#include "engine/gpu/command_list.h"
#include "engine/gpu/context.h"
#include "engine/light/light_sampler.h"
#include "engine/light/path_depth.h"
#include "engine/render/chain_layer.h"
#include "engine/render/g_buffer_pass.h"
#include "engine/render/scene_geometry.h"
#include "engine/render/vpl_renderer.h"
#include "engine/scene/scene_loader.h"
#include "engine/trace/accel.h"
#include "shaders/shared/chain_record.h"
#include "tests/gpu/gpu_test.h"

namespace mvpl::aov {
namespace {

using AovGpuTest = gpu::testing::GpuTest;

struct Receiver {
    Rgb albedo{0.0f};
    Vec3 normal{0.0f};
    Vec3 position{0.0f};
};

constexpr uint64_t kPositions = 4;

struct GpuAovs {
    std::vector<Receiver> mean;
    std::vector<int> covered;  // positions at which the pixel saw a surface (or a chain)
    int chained = 0;           // pixel positions shaded from a chain record
};

// What the GPU shades at the render's positions: the G-buffer's texel, or the chain layer's
// record where the chain continues the pixel (black where it ends nowhere).
GpuAovs gpu_aovs(gpu::Context& context, const scene::Scene& s, const trace::Accel& accel,
                 const integrator::Estimate& e) {
    const uint32_t w = e.render.width, h = e.render.height;
    const SubpixelSchedule schedule = render::subpixel_schedule(e.render);
    const render::SceneGeometry geometry(context, s);
    render::GBufferPass pass(context, geometry, w, h);
    std::unique_ptr<render::ChainLayer> chains;
    if (e.render.chains.enabled())
        chains = std::make_unique<render::ChainLayer>(context, s, accel, w, h);
    GpuAovs out{std::vector<Receiver>(w * h), std::vector<int>(w * h, 0), 0};
    for (uint64_t p = 0; p < kPositions; ++p) {
        context.submit_and_wait(
            [&](gpu::CommandList& cmd) { pass.record(cmd, s.camera, schedule.position(p)); });
        const std::vector<render::GBufferTexel> texels = pass.download();
        std::vector<shared::ChainRecord> records(w * h);
        if (chains) {
            chains->trace(s.camera, schedule.position(p), p, e.render.chains, e.render.chain_seed);
            std::memcpy(records.data(), chains->records().mapped(),
                        records.size() * sizeof(shared::ChainRecord));
        }
        for (size_t i = 0; i < texels.size(); ++i) {
            Receiver r;
            const shared::ChainRecord& c = records[i];
            if (c.state == shared::kChainReceiver) {
                const auto v = [](const shared::vec3& a) { return Vec3(a[0], a[1], a[2]); };
                r = Receiver{v(c.base_color), v(c.shading_normal), v(c.position)};
                ++out.chained;
            } else if (c.state == shared::kChainBlack) {
                ++out.chained;
            } else if (texels[i].covered) {
                const render::GBufferTexel& t = texels[i];
                // The G-buffer keeps the unflipped normal (the shading pass flips back faces).
                const float side = !t.front_face && t.double_sided ? -1.0f : 1.0f;
                r = Receiver{t.closure.base_color, side * t.shading_normal, t.position};
            } else {
                continue;
            }
            ++out.covered[i];
            out.mean[i].albedo += r.albedo / float(kPositions);
            out.mean[i].normal += r.normal / float(kPositions);
            out.mean[i].position += r.position / float(kPositions);
        }
    }
    return out;
}

// Renders `scene`'s AOVs at kPositions positions on the CPU and on the GPU; returns the GPU's
// chained pixel positions.
int expect_agreement(gpu::Context& context, const scene::Scene& s, bool chains) {
    integrator::Estimate e;
    e.render.width = 32;
    e.render.height = 24;
    e.render.subpixel_rotation = subpixel_rotation(9);
    e.render.chain_seed = 9;
    if (chains) {
        e.render.chains.max_roughness = light::kDefaultChainRoughness;
        e.render.chains.max_depth = light::kDefaultMaxDepth;
    }
    const uint64_t vpls = uint64_t(e.render.batch) * e.render.batches_per_position * kPositions;
    EXPECT_EQ(render::subpixel_schedule(e.render).positions_after(vpls), kPositions);
    const trace::Accel accel(s);
    const light::LightSampler lights(s);
    const GpuAovs gpu = gpu_aovs(context, s, accel, e);
    const std::vector<ChannelImage> cpu =
        render_aovs({&s, &accel, &lights, &s.camera}, e, vpls,
                    parse_aov_list("albedo,normal,position", "--aov"));
    int compared = 0, bad = 0;
    std::ostringstream seen;
    const float scale = glm::length(s.bounds().hi - s.bounds().lo);
    for (size_t i = 0; i < gpu.mean.size(); ++i) {
        if (gpu.covered[i] != int(kPositions)) continue;  // a silhouette: the background mixes in
        ++compared;
        float d_albedo = 0.0f, d_normal = 0.0f, d_position = 0.0f;
        for (int c = 0; c < 3; ++c) {
            const auto diff = [&](int image, float want) {
                return std::abs(cpu[size_t(image)].values[3 * i + size_t(c)] - want);
            };
            d_albedo = std::max(d_albedo, diff(0, gpu.mean[i].albedo[c]));
            d_normal = std::max(d_normal, diff(1, gpu.mean[i].normal[c]));
            d_position = std::max(d_position, diff(2, gpu.mean[i].position[c]));
        }
        if (d_albedo > 1e-3f || d_normal > 1e-3f || d_position > 1e-4f * scale) {
            // E.g. a floor tile's seam: the same point, the neighbouring tile's colour.
            if (bad++ < 8) {
                seen << "pixel " << i % 32 << "," << i / 32 << ": albedo " << d_albedo
                     << ", normal " << d_normal << ", position " << d_position << "\n";
            }
        }
    }
    EXPECT_GT(compared, int(gpu.mean.size()) / 2);
    EXPECT_LE(bad, compared / 50) << seen.str();
    return gpu.chained;
}

TEST_F(AovGpuTest, AgreesWithTheGBuffersOfATexturedScene) {
    const scene::Scene s = scene::load_scene(MVPL_ASSETS_DIR "/textured/textured.gltf");
    expect_agreement(context(), s, false);
}

// assets/glossy: a mirror-like and a glass object, whose pixels the GPU shades from the chain
// layer's records.
TEST_F(AovGpuTest, AgreesWithTheChainLayerWhereChainsContinue) {
    const scene::Scene s = scene::load_scene(MVPL_ASSETS_DIR "/glossy/glossy.gltf");
    EXPECT_GT(expect_agreement(context(), s, true), 32) << "the scene should have chained pixels";
}

}  // namespace
}  // namespace mvpl::aov
