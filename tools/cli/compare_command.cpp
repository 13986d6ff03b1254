// `mvpl compare`: error of one image against a reference.
#include <cstdio>

#include "engine/core/error.h"
#include "engine/core/image.h"
#include "engine/core/image_metrics.h"
#include "tools/cli/arg_parser.h"
#include "tools/cli/commands.h"

namespace mvpl::cli {

int run_compare(const Args& args) {
    std::string image_path, reference_path;
    int block = 1;
    ArgParser parser(
        "compare",
        "Prints the error of IMAGE against REFERENCE: relMSE = mean((x-r)^2/(r^2+0.01)),\n"
        "RMSE, mean absolute error and the per-channel ratio of means.");
    parser.add_positional("IMAGE", &image_path, "EXR image");
    parser.add_positional("REFERENCE", &reference_path, "EXR reference of the same size");
    parser.add_int("--block", &block, "compare K×K block averages (for differing pixel filters)");
    if (!parser.parse(args)) return 0;
    if (block < 1) throw UsageError("compare: --block must be at least 1");
    const Image image = read_exr(image_path);
    const Image reference = read_exr(reference_path);
    if (image.width() != reference.width() || image.height() != reference.height()) {
        throw InputError(image_path, "size " + std::to_string(image.width()) + "x" +
                                         std::to_string(image.height()) +
                                         " differs from the reference's " +
                                         std::to_string(reference.width()) + "x" +
                                         std::to_string(reference.height()));
    }
    if (block > image.width() || block > image.height())
        throw UsageError("compare: --block is larger than the image");
    const ImageError e =
        compare_images(block_average(image, block), block_average(reference, block));
    std::printf("relMSE %.6g\nRMSE %.6g\nmean_abs %.6g\nmean_ratio %.6f %.6f %.6f\n", e.rel_mse,
                e.rmse, e.mean_abs, e.mean_ratio.x, e.mean_ratio.y, e.mean_ratio.z);
    std::printf("rel_err_p999 %.6g\nmax_ratio %.6g\n", e.rel_err_p999, e.max_ratio);
    return 0;
}

}  // namespace mvpl::cli
