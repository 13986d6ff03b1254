// Row-column sampling through the integrator on the GPU renderer against the same on the CPU
// oracle: the same seeds draw the same representatives (the reduced matrix is the CPU's in both),
// and the GPU shades them as it shades any VPL, within the shadow maps' band (docs/results.md,
// "GPU against the CPU oracle": relMSE ≤ 1.25 · 2/shadow_res). With the GPU's matrix the
// representatives' image is the pool's in expectation, as with the CPU's.
#include <gtest/gtest.h>

#include <cstdio>

#include "engine/core/image_metrics.h"
#include "engine/integrator/gpu_columns.h"
#include "engine/integrator/vpl_integrator.h"
#include "engine/light/light_sampler.h"
#include "engine/render/vpl_renderer.h"
#include "engine/scene/scene_loader.h"
#include "engine/trace/accel.h"
#include "tests/gpu/gpu_test.h"
#include "tests/manylights/unbiased_draws.h"

namespace mvpl {
namespace {

using RowColumnGpuTest = gpu::testing::GpuTest;

TEST_F(RowColumnGpuTest, RepresentativesOnTheGpuMatchTheOracle) {
    const scene::Scene scene = scene::load_scene(MVPL_ASSETS_DIR "/cornell-box/cbox.gltf");
    const trace::Accel accel(scene);
    const light::LightSampler lights(scene);
    integrator::Estimate e;
    e.render.width = e.render.height = 32;
    e.render.shadow_resolution = 256;
    e.compensate = false;
    e.caustics = false;
    e.sampling.seed = 5;
    e.many_lights.pool = 256;
    e.many_lights.rows = 32;
    e.many_lights.clusters = 32;
    e.many_lights.matrix =
        manylights::MatrixDevice::cpu;  // the CPU's matrix in both: the same representatives
    const integrator::SceneView view{&scene, &accel, &lights, &scene.camera};
    auto run = [&](gpu::Context* gpu, integrator::IntegratorStats* stats) {
        integrator::VplIntegrator it(view, gpu, 1, nullptr);
        it.begin(view, e, integrator::Pacing::Fixed);
        it.advance(256);
        it.advance(256);
        Image image = it.finish();
        *stats = it.stats();
        return image;
    };
    integrator::IntegratorStats gpu_stats, cpu_stats;
    const Image gpu = run(&context(), &gpu_stats), cpu = run(nullptr, &cpu_stats);
    EXPECT_EQ(gpu_stats.shaded, cpu_stats.shaded);
    EXPECT_LT(gpu_stats.shaded, gpu_stats.vpls / 4);
    const double bound = 1.25 * 2.0 / 256.0;
    const double rel_mse = compare_images(gpu, cpu).rel_mse;
    std::printf("GPU against the oracle: relMSE %.3g (bound %.3g), %zu of %zu VPLs shaded\n",
                rel_mse, bound, gpu_stats.shaded, gpu_stats.vpls);
    EXPECT_LT(rel_mse, bound);
}

TEST_F(RowColumnGpuTest, UnbiasedOverDrawsWithTheGpuMatrix) {
    const manylights_test::Cornell& c = manylights_test::cornell();
    render::VplRenderer renderer(context(), c.scene, &c.accel);
    render::RenderOptions ro;
    ro.width = ro.height = manylights_test::kRes;
    renderer.begin(c.scene.camera, ro);
    integrator::GpuColumns columns(renderer, 64);
    manylights_test::expect_unbiased(32, 32, 160, &columns);
}

}  // namespace
}  // namespace mvpl
