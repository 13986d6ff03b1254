#pragma once
// An image's error against a reference as one JSON object (`mvpl compare --json`, and the Python
// module's compare(), which returns it as a dict): the names of compare's text output.
#include <nlohmann/json.hpp>
#include <optional>

#include "engine/core/image_metrics.h"

namespace mvpl::cli {

// reference_noise and relMSE_vs_truth only when the references' own noise is known (several
// references).
nlohmann::json error_json(const ImageError& e, std::optional<double> reference_noise);

}  // namespace mvpl::cli
