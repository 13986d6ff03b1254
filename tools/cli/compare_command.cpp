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
    std::string region;
    ArgParser parser(
        "compare",
        "Prints the error of IMAGE against REFERENCE: relMSE = mean((x-r)^2/(r^2+0.01)),\n"
        "RMSE, mean absolute error and the per-channel ratio of means.");
    parser.add_positional("IMAGE", &image_path, "EXR image");
    parser.add_positional("REFERENCE", &reference_path, "EXR reference of the same size");
    parser.add_int("--block", &block, "compare K×K block averages (for differing pixel filters)");
    parser.add_string("--region", &region,
                      "X,Y,W,H: compare only the W×H pixels from (X, Y) (an object's pixels)");
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
    Image a = image, b = reference;
    if (!region.empty()) {
        int x = 0, y = 0, w = 0, h = 0;
        char tail = 0;
        if (std::sscanf(region.c_str(), "%d,%d,%d,%d%c", &x, &y, &w, &h, &tail) != 4)
            throw UsageError("compare: --region must be X,Y,W,H (integers), not '" + region + "'");
        a = crop(image, x, y, w, h);
        b = crop(reference, x, y, w, h);
    }
    if (block > a.width() || block > a.height())
        throw UsageError("compare: --block is larger than the image");
    const ImageError e = compare_images(block_average(a, block), block_average(b, block));
    std::printf("relMSE %.6g\nRMSE %.6g\nmean_abs %.6g\nmean_ratio %.6f %.6f %.6f\n", e.rel_mse,
                e.rmse, e.mean_abs, e.mean_ratio.x, e.mean_ratio.y, e.mean_ratio.z);
    std::printf("rel_err_p999 %.6g\nmax_ratio %.6g\n", e.rel_err_p999, e.max_ratio);
    return 0;
}

}  // namespace mvpl::cli
