#include "tools/cli/error_json.h"

namespace mvpl::cli {

nlohmann::json error_json(const ImageError& e, std::optional<double> noise) {
    nlohmann::json j = {{"relMSE", e.rel_mse},
                        {"RMSE", e.rmse},
                        {"mean_abs", e.mean_abs},
                        {"mean_ratio", {e.mean_ratio.x, e.mean_ratio.y, e.mean_ratio.z}},
                        {"rel_err_p999", e.rel_err_p999},
                        {"max_ratio", e.max_ratio}};
    if (noise) {
        j["reference_noise"] = *noise;
        j["relMSE_vs_truth"] = e.rel_mse - *noise;
    }
    return j;
}

}  // namespace mvpl::cli
