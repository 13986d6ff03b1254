// The preview's error view (tools/preview/frame_variance.h) against the error it estimates: its
// mean square relative standard error, from the variance between frames, against the relMSE
// that `mvpl render` of the same VPLs has against a converged render.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "engine/core/image.h"
#include "engine/core/image_metrics.h"
#include "tests/window/preview_run.h"

namespace mvpl::test {
namespace {

const std::string kScene = std::string(MVPL_ASSETS_DIR) + "/cornell-box/cbox.gltf";

double mean_square(const Image& image) {
    double sum = 0.0;
    for (const Rgb& p : image.pixels())
        for (int c = 0; c < 3; ++c)
            sum += double(p[c]) * double(p[c]);
    return sum / double(3 * image.pixels().size());
}

// Three seeds of 64 light paths, 16 frames of 4 paths each (Monte Carlo: independent frames; no
// compensation or caustics, whose CPU images are not paced by the paths), at the pixel centres:
// the view estimates the VPLs' variance, not the error of too few sub-pixel positions (with
// them the actual relMSE here is 3–4× the estimate: silhouettes at 48×32). The clamp's bias is
// the same in the converged render, whose own variance (1024 paths) adds 1/16 to the actual
// relMSE. One seed's actual relMSE is itself a noisy draw (a few VPLs light the whole box;
// measured ratios 0.74–1.04), so the sums over the seeds are compared, within a factor of 2
// either way.
TEST(PreviewErrorView, EstimatesTheRelMseOfItsVpls) {
    if (!have_xvfb()) GTEST_SKIP() << "xvfb-run is not installed (apt install xvfb)";
    const std::filesystem::path dir = preview_temp_dir();
    const std::filesystem::path script = dir / "error-view.txt";
    std::ofstream(script) << "0 view error\n";
    const std::string size =
        shell_quote(kScene) + " --res 48x32 --no-compensate --no-caustics --no-jitter";
    const std::string converged = (dir / "converged.exr").string();
    const CommandResult reference = run_mvpl_gpu("render " + size + " --vpls 1024 --seed 99 -o " +
                                                 shell_quote(converged) + " --quiet");
    ASSERT_EQ(reference.exit_code, 0) << reference.err;
    double predicted = 0.0, actual = 0.0;
    for (const int seed : {3, 4, 5}) {
        const std::string common = size + " --vpls 64 --seed " + std::to_string(seed);
        const std::string view = (dir / "error.exr").string(), image = (dir / "image.exr").string();
        const CommandResult p = run_preview(common + " --paths-per-frame 4 --frames 17 --script " +
                                            shell_quote(script.string()) + " --screenshot " +
                                            shell_quote(view) + " --quiet");
        ASSERT_EQ(p.exit_code, 0) << p.err;
        const CommandResult r =
            run_mvpl_gpu("render " + common + " -o " + shell_quote(image) + " --quiet");
        ASSERT_EQ(r.exit_code, 0) << r.err;
        const double estimate = mean_square(read_exr(view));
        const double error = compare_images(read_exr(image), read_exr(converged)).rel_mse;
        std::printf("seed %d: estimated relMSE %.4g, actual %.4g\n", seed, estimate, error);
        EXPECT_GT(estimate, 0.0);  // not a black view
        predicted += estimate;
        actual += error;
    }
    EXPECT_GT(predicted, 0.5 * actual);
    EXPECT_LT(predicted, 2.0 * actual);
}

}  // namespace
}  // namespace mvpl::test
