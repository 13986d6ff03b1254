// `mvpl compare`: error of one image against a reference.
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/error.h"
#include "engine/core/finite_check.h"
#include "engine/core/image.h"
#include "engine/core/image_metrics.h"
#include "engine/core/reference_noise.h"
#include "tools/cli/arg_parser.h"
#include "tools/cli/commands.h"
#include "tools/cli/error_json.h"

namespace mvpl::cli {

namespace {

// The error as text, a `name value` line each, or as one JSON object with the same names (for
// scripts); reference_noise and relMSE_vs_truth only with several references.
void print_error(const ImageError& e, std::optional<double> noise, bool json) {
    if (json) {
        std::printf("%s\n", error_json(e, noise).dump().c_str());
        return;
    }
    std::printf("relMSE %.6g\nRMSE %.6g\nmean_abs %.6g\nmean_ratio %.6f %.6f %.6f\n", e.rel_mse,
                e.rmse, e.mean_abs, e.mean_ratio.x, e.mean_ratio.y, e.mean_ratio.z);
    std::printf("rel_err_p999 %.6g\nmax_ratio %.6g\n", e.rel_err_p999, e.max_ratio);
    if (noise)
        std::printf("reference_noise %.6g\nrelMSE_vs_truth %.6g\n", *noise, e.rel_mse - *noise);
}

// k where `image` is k times `reference`'s size on both axes (k ≥ 2), else 0.
int size_multiple(const Image& image, const Image& reference) {
    const int k = image.width() / reference.width();
    const bool whole = k >= 2 && image.width() == k * reference.width() &&
                       image.height() == k * reference.height();
    return whole ? k : 0;
}

}  // namespace

int run_compare(const Args& args) {
    std::string image_path, reference_path;
    int block = 1;
    std::string region;
    std::vector<std::string> more_references;
    bool json = false;
    ArgParser parser(
        "compare",
        "Prints the error of IMAGE against REFERENCE: relMSE = mean((x-r)^2/(r^2+0.01)),\n"
        "RMSE, mean absolute error and the per-channel ratio of means. With --and-ref, against\n"
        "the mean of several independent references, and the references' own share of relMSE.");
    parser.add_positional("IMAGE", &image_path, "EXR image");
    parser.add_positional("REFERENCE", &reference_path,
                          "EXR reference of the same size, or of IMAGE's size divided by a whole "
                          "number k on both axes: IMAGE's k×k means, the reference's "
                          "box-filtered pixels, are compared (a render at 512² against a 256² "
                          "reference); --region and --block then count reference pixels");
    parser.add_int("--block", &block, "compare K×K block averages (for differing pixel filters)",
                   "K");
    parser.add_string("--region", &region,
                      "compare only the W×H pixels from (X, Y) (an object's pixels)", "X,Y,W,H");
    parser.add_strings("--and-ref", &more_references,
                       "another independent reference (a different seed, the same sample count): "
                       "the references are averaged, and their noise's share of relMSE "
                       "(reference_noise) and relMSE less it (relMSE_vs_truth) are printed",
                       "FILE");
    parser.add_flag("--json", &json, "print the error as one JSON object with the same names");
    if (!parser.parse(args)) return 0;
    if (block < 1) throw UsageError("compare: --block must be at least 1");
    Image image = read_finite_exr(image_path);
    std::vector<Image> references{read_finite_exr(reference_path)};
    if (const int k = size_multiple(image, references[0])) {
        image = block_average(image, k);
        std::fprintf(stderr, "compare: %s is %d× the reference's size: its %d×%d means compared\n",
                     image_path.c_str(), k, k, k);
    }
    for (const std::string& path : more_references)
        references.push_back(read_finite_exr(path));
    for (size_t i = 0; i < references.size(); ++i) {
        const Image& reference = references[i];
        if (image.width() == reference.width() && image.height() == reference.height()) continue;
        if (i == 0) {
            throw InputError(image_path, "size " + std::to_string(image.width()) + "x" +
                                             std::to_string(image.height()) +
                                             " differs from the reference's " +
                                             std::to_string(reference.width()) + "x" +
                                             std::to_string(reference.height()));
        }
        throw InputError(more_references[i - 1], "size differs from the image's");
    }
    // The region and the blocks apply to every reference alike.
    auto prepare = [&](const Image& full) {
        Image part = full;
        if (!region.empty()) {
            int x = 0, y = 0, w = 0, h = 0;
            char tail = 0;
            if (std::sscanf(region.c_str(), "%d,%d,%d,%d%c", &x, &y, &w, &h, &tail) != 4)
                throw UsageError("compare: --region must be X,Y,W,H (integers), not '" + region +
                                 "'");
            part = crop(full, x, y, w, h);
        }
        if (block > part.width() || block > part.height())
            throw UsageError("compare: --block is larger than the image");
        return block_average(part, block);
    };
    for (Image& reference : references)
        reference = prepare(reference);
    const ImageError e = compare_images(prepare(image), average_images(references));
    print_error(
        e, references.size() > 1 ? std::optional(reference_noise(references)) : std::nullopt, json);
    return 0;
}

}  // namespace mvpl::cli
